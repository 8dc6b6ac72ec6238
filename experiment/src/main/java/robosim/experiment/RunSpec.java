package robosim.experiment;

import java.nio.file.Path;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * One run of an experiment, every value filled in: what a worker needs to run it and what its row
 * says of it. The same experiment file gives the same run for the same index, wherever it runs.
 *
 * @param index     its index in the sweep, from 0: combinations in the file's order, each with its
 *                  replicates in turn
 * @param factors   the value of each factor, in the file's order
 * @param replicate the replicate, from 1
 * @param seed      the run's seed ({@code firstSeed + replicate - 1}: each combination meets the same
 *                  seeds, so the same mazes)
 * @param world     the world it runs in
 * @param programs  the robot programs, in the order they take the world's robots
 * @param comms     the communications settings it changes
 * @param steps     its step limit
 */
public record RunSpec(int index, Map<String, String> factors, int replicate, long seed, WorldPlan world,
                      List<ProgramPlan> programs, CommsPlan comms, long steps) {
    /** Copies the collections. */
    public RunSpec {
        factors = Collections.unmodifiableMap(new LinkedHashMap<>(factors));
        programs = List.copyOf(programs);
    }

    /** Where the world comes from. */
    public sealed interface WorldPlan permits MazePlan, FilePlan {
        /** @return the world properties the run sets, beside the world's own */
        Map<String, String> properties();
    }

    /**
     * A perfect maze carved from a seed ({@link robosim.env.world.maze.Maze}), with the gold in the
     * cell farthest from the start and the robots in the cells nearest it.
     *
     * @param width      cells across
     * @param height     cells up
     * @param cellSize   mm
     * @param mazeSeed   the maze's seed
     * @param robotFile  the robots' parameter file (a shipped name such as {@code p3dx}, or a path)
     * @param properties world properties to set
     */
    public record MazePlan(int width, int height, int cellSize, long mazeSeed, String robotFile,
                           Map<String, String> properties) implements WorldPlan {
    }

    /**
     * A world file.
     *
     * @param file       the file
     * @param properties world properties to set
     */
    public record FilePlan(Path file, Map<String, String> properties) implements WorldPlan {
    }

    /** How a program's robots reach the Environment. */
    public enum Link {
        /** Threads of the run's JVM, over the in-process link: no sockets. */
        IN_PROCESS,
        /** Each robot in a JVM of its own, over TCP, as {@code robosim robot} runs it. */
        JVM;

        /** @return its name in the file: {@code in-process} or {@code jvm} */
        public String fileName() {
            return this == IN_PROCESS ? "in-process" : "jvm";
        }

        /**
         * @param name a link's name in the file or on the command line
         * @return the link, or null if the name is neither {@code in-process} nor {@code jvm}
         */
        public static Link ofFileName(String name) {
            for (Link l : values()) {
                if (l.fileName().equals(name)) {
                    return l;
                }
            }
            return null;
        }
    }

    /**
     * A robot program and the robots that run it.
     *
     * @param className the class with {@code main(NAME, HOST, PORT, ARGS...)}
     * @param count     how many robots, or -1 for all the world's robots no program before it took
     * @param args      its arguments after the robot's name, host and port
     * @param link      how its robots reach the Environment
     */
    public record ProgramPlan(String className, int count, List<String> args, Link link) {
        /** Copies the list. */
        public ProgramPlan {
            args = List.copyOf(args);
        }
    }

    /**
     * The communications settings a run changes; null leaves the world's.
     *
     * @param range      mm a message carries, 0 for any distance
     * @param loss       the chance a message is lost on its way to each recipient, 0 to 1
     * @param latency    steps a message takes, at least 1
     * @param wallsBlock whether walls stop messages
     */
    public record CommsPlan(Double range, Double loss, Integer latency, Boolean wallsBlock) {
        /** Changes nothing. */
        public static final CommsPlan NONE = new CommsPlan(null, null, null, null);
    }
}
