package robosim.env.net;

import java.util.List;
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
 */
public record RunReport(long steps, long timeMs, String endReason, List<RobotSummary> robots, long wallNanos,
                        Find find, long connectedNanoTime) {
    /** Copies the list so the record stays immutable. */
    public RunReport {
        robots = List.copyOf(robots);
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
        this(steps, timeMs, endReason, robots, wallNanos, find, 0);
    }
}
