package robosim.env.net;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import robosim.env.core.Find;
import robosim.env.core.RobotSummary;
import robosim.protocol.Snapshot;

/**
 * How a run ended.
 *
 * @param steps     steps simulated
 * @param timeMs    simulated time, ms
 * @param endReason why it ended, in words
 * @param ending    how it ended, for machines ({@link RunEnding#wireName()} in files)
 * @param robots    every robot at the end, in the world file's order, with the figures the
 *                  Environment counts for each (distance, collisions, stalls, messages)
 * @param wallNanos wall-clock time the steps took, from the first step to the end (for benchmarks)
 * @param find      the confirmed find of the world's gold, or null
 * @param connectedNanoTime {@link System#nanoTime()} when every robot had connected (and the awaited
 *                  viewers had attached), just before the first step: comparable only with other
 *                  {@code System.nanoTime()} readings of the Environment's JVM (for benchmarks that
 *                  time loading and connecting); 0 if unknown
 * @param departures the robots that left, were dropped or were lost before the end, in the order they
 *                  went, each with the step and the reason; a robot that came back may be in it again
 * @param joins     the robots that joined after the run started (late, back, or spawned in an open
 *                  world), in the order they came
 * @param absent    the robots of the world that never connected to this run (an open world's, or a
 *                  run's after a restart or load that ended before they came), in the world's order
 * @param metrics   the metrics the robots reported, the last value of each: robot name to metric name
 *                  to value, every robot of the world in its order (an empty map for one that reported
 *                  none), each robot's metrics in the order it first reported them
 * @param endRequest the robot's request that ended the run (robot, step, reason), or null: with
 *                  {@link RunEnding#ROBOT_ENDED}, and only then
 */
public record RunReport(long steps, long timeMs, String endReason, RunEnding ending, List<RobotSummary> robots,
                        long wallNanos, Find find, long connectedNanoTime, List<Departure> departures, List<Join> joins,
                        List<String> absent, Map<String, Map<String, Double>> metrics,
                        Snapshot.EndRequest endRequest) {
    /** Copies the lists and the maps so the record stays immutable, and in order. */
    public RunReport {
        if (ending == null) {
            throw new IllegalArgumentException("a run report needs its ending, with the reason '" + endReason + "'");
        }
        robots = List.copyOf(robots);
        departures = List.copyOf(departures);
        joins = List.copyOf(joins);
        absent = List.copyOf(absent);
        Map<String, Map<String, Double>> copy = new LinkedHashMap<>();
        metrics.forEach((robot, own) -> copy.put(robot, Collections.unmodifiableMap(new LinkedHashMap<>(own))));
        metrics = Collections.unmodifiableMap(copy);
    }

    /**
     * @param robot a robot's name
     * @return how it last went before the end of the run, or empty if it ran to the end (or came back
     *         after it went: a join takes part from a later step than the one its robot went at)
     */
    public Optional<Departure> departure(String robot) {
        Departure last = null;
        for (Departure d : departures) {
            if (d.robot().equals(robot)) {
                last = d;
            }
        }
        Departure went = last;
        if (went == null || joins.stream().anyMatch(j -> j.robot().equals(robot) && j.step() > went.step())) {
            return Optional.empty();
        }
        return Optional.of(went);
    }

    /**
     * @param robot a robot's name
     * @return how it joined after the run started, in order; empty if it was there from the start
     */
    public List<Join> joinsOf(String robot) {
        return joins.stream().filter(j -> j.robot().equals(robot)).toList();
    }
}
