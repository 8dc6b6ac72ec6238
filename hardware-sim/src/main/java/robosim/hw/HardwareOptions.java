package robosim.hw;

/**
 * Timeouts of a robot's link.
 *
 * @param connectTimeoutMs   longest wait to connect and to be welcomed
 * @param stepReadTimeoutMs  longest wait for the next step before giving up on the Environment
 *                           (the Environment may be waiting for other robots to connect)
 * @param yieldWarningMs     how long the robot's code may run without yielding before a warning
 */
public record HardwareOptions(long connectTimeoutMs, long stepReadTimeoutMs, long yieldWarningMs) {
    /** @return 10 s to connect, 10 min for a step, a warning after 5 s without a yield */
    public static HardwareOptions defaults() {
        return new HardwareOptions(10_000, 600_000, 5_000);
    }
}
