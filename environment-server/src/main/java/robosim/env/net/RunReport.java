package robosim.env.net;

import java.util.List;
import java.util.Optional;
import robosim.env.core.Find;
import robosim.env.core.RobotSummary;

/**
 * How a run ended.
 *
 * @param steps     steps simulated
 * @param timeMs    simulated time, ms
 * @param endReason why it ended
 * @param robots    every robot at the end, in the world file's order
 * @param wallNanos wall-clock time the steps took, from the first step to the end (for benchmarks)
 * @param find      the confirmed find of the world's gold, or null
 * @param connectedNanoTime {@link System#nanoTime()} when every robot had connected (and the awaited
 *                  viewers had attached), just before the first step: comparable only with other
 *                  {@code System.nanoTime()} readings of the Environment's JVM (for benchmarks that
 *                  time loading and connecting); 0 if unknown
 * @param departures the robots that left, were dropped or were lost before the end, in the order they
 *                  went, each with the step and the reason; the others ran to the end
 */
public record RunReport(long steps, long timeMs, String endReason, List<RobotSummary> robots, long wallNanos,
                        Find find, long connectedNanoTime, List<Departure> departures) {
    /** Copies the lists so the record stays immutable. */
    public RunReport {
        robots = List.copyOf(robots);
        departures = List.copyOf(departures);
    }

    /**
     * A report in which every robot ran to the end.
     *
     * @param steps     steps simulated
     * @param timeMs    simulated time, ms
     * @param endReason why it ended
     * @param robots    every robot at the end, in the world file's order
     * @param wallNanos wall-clock time the steps took
     * @param find      the confirmed find of the world's gold, or null
     * @param connectedNanoTime {@link System#nanoTime()} when every robot had connected, or 0
     */
    public RunReport(long steps, long timeMs, String endReason, List<RobotSummary> robots, long wallNanos, Find find,
                     long connectedNanoTime) {
        this(steps, timeMs, endReason, robots, wallNanos, find, connectedNanoTime, List.of());
    }

    /**
     * @param robot a robot's name
     * @return how it went before the end of the run, or empty if it ran to the end
     */
    public Optional<Departure> departure(String robot) {
        return departures.stream().filter(d -> d.robot().equals(robot)).findFirst();
    }

    /**
     * A report that does not know when the robots connected ({@link #connectedNanoTime()} is 0).
     *
     * @param steps     steps simulated
     * @param timeMs    simulated time, ms
     * @param endReason why it ended
     * @param robots    every robot at the end, in the world file's order
     * @param wallNanos wall-clock time the steps took
     * @param find      the confirmed find of the world's gold, or null
     */
    public RunReport(long steps, long timeMs, String endReason, List<RobotSummary> robots, long wallNanos, Find find) {
        this(steps, timeMs, endReason, robots, wallNanos, find, 0, List.of());
    }
}
