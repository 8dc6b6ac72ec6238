package robosim.experiment;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import robosim.env.world.World;
import robosim.env.world.maze.GoldBound;
import robosim.env.world.maze.Maze;
import robosim.env.world.maze.MazeWorldWriter;
import robosim.env.world.xml.WorldReader;
import robosim.experiment.RunRobots.RunFailure;
import robosim.experiment.RunSpec.FilePlan;
import robosim.experiment.RunSpec.MazePlan;
import robosim.experiment.RunSpec.ProgramPlan;
import robosim.params.RobotParameterFiles;

/** The world of a run: a generated maze (written under the results folder) or a world file. */
final class RunWorlds {
    private RunWorlds() {
    }

    /** A run's world, with its lower bound on the steps to find the gold (null for a world without gold). */
    record Made(World world, Long lowerBound) {
    }

    /**
     * @param run the run
     * @param out the results folder; mazes go to its {@code worlds/}
     * @return the world, with the robots its programs ask for and the properties the run sets
     * @throws IOException if a maze cannot be written or the world cannot be read
     * @throws RunFailure  if the world has fewer robots than the programs ask for
     */
    static Made make(RunSpec run, Path out) throws IOException {
        int wanted = 0;
        boolean rest = false;
        for (ProgramPlan p : run.programs()) {
            if (p.count() < 0) {
                rest = true;
            } else {
                wanted += p.count();
            }
        }
        if (run.world() instanceof MazePlan m) {
            Maze maze = Maze.generate(m.width(), m.height(), m.mazeSeed());
            Path params = RobotParameterFiles.resolve(m.robotFile()).toAbsolutePath();
            String xml = MazeWorldWriter.write(maze, String.format(Locale.ROOT, "maze-%dx%d-%d", m.width(), m.height(),
                    m.mazeSeed()), m.cellSize(), wanted, params.toString().replace('\\', '/'));
            // named by its text: runs at once that need the same maze with other robots never share a file
            Path file = out.resolve("worlds").resolve(String.format(Locale.ROOT, "maze-%dx%d-%d-%s.xml", m.width(),
                    m.height(), m.mazeSeed(), ExperimentFiles.fingerprint(xml)));
            if (!Files.exists(file)) {
                AtomicFiles.write(file, xml);
            }
            World world = properties(WorldReader.read(file), m.properties());
            return new Made(world, bound(world));
        }
        FilePlan f = (FilePlan) run.world();
        World world = WorldReader.read(f.file());
        int named = world.robots().size();
        if (wanted > named || (!rest && wanted == 0)) {
            throw new RunFailure("world " + f.file() + " names " + named + " robot(s); the programs ask for " + wanted);
        }
        World team = properties(rest ? world : world.withFirstRobots(wanted), f.properties());
        return new Made(team, bound(team));
    }

    /** @return the world's lower bound on the steps to find its gold, or null without gold or robots */
    private static Long bound(World world) {
        return world.gold() == null || world.robots().isEmpty() ? null : GoldBound.steps(world);
    }

    /**
     * A world file must read, and a maze's robot parameter file must be found, before any run starts.
     *
     * @param e   the experiment
     * @param run one of its runs
     * @throws ExperimentFileException naming the line of the world or robot file that does not read
     */
    static void check(Experiment e, RunSpec run) {
        if (run.world() instanceof RunSpec.MazePlan m) {
            try {
                RobotParameterFiles.load(m.robotFile());
            } catch (IllegalArgumentException x) {
                throw new ExperimentFileException(e.file(), e.world().robotFile() == null ? 0 : e.world().robotFile().line(),
                        "world.maze.robotFile: " + x.getMessage());
            }
            return;
        }
        Path world = ((RunSpec.FilePlan) run.world()).file();
        if (!Files.isRegularFile(world)) {
            throw new ExperimentFileException(e.file(), e.world().file().line(), "world.file is " + world
                    + ", which does not exist (a world file's path is relative to the experiment file)");
        }
        try {
            WorldReader.read(world);
        } catch (RuntimeException x) {
            throw new ExperimentFileException(e.file(), e.world().file().line(), "world.file " + world
                    + " breaks a rule: " + x.getMessage());
        }
    }

    private static World properties(World world, Map<String, String> set) {
        if (set.isEmpty()) {
            return world;
        }
        Map<String, String> all = new LinkedHashMap<>(world.properties());
        all.putAll(set);
        return world.withProperties(all);
    }
}
