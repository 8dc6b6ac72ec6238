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
 */
public record RunReport(long steps, long timeMs, String endReason, List<RobotSummary> robots, long wallNanos,
                        Find find) {
    /** Copies the list so the record stays immutable. */
    public RunReport {
        robots = List.copyOf(robots);
    }
}
