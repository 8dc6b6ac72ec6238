package robosim.aria;

import java.util.logging.Logger;

/**
 * What {@link ArRobot} keeps of its cycles besides the counter, as ARIA's {@code ArRobot} does
 * (ArRobot.cpp): the cycle warning time (a cycle's tasks that take longer, in wall-clock time, are
 * logged, as ARIA logs a slow cycle, unless the cycle was told not to), and how many states (ARIA's
 * motor packets) and how many states with new sonar readings came in the last whole simulated second.
 */
final class CycleStats {
    private static final Logger LOG = Logger.getLogger(ArRobot.class.getName());
    /** ARIA's default cycle warning time, ms. */
    static final int DEFAULT_WARNING_MS = 250;

    volatile int warningMs = DEFAULT_WARNING_MS;
    volatile boolean noTimeWarningThisCycle;
    private long second = -1;
    private int motorNow;
    private int sonarNow;
    private int motorLast;
    private int sonarLast;

    /** Counts a state of the given simulated time. */
    synchronized void count(long timeMs, boolean sonarNew) {
        long sec = timeMs / 1000;
        if (sec != second) {
            motorLast = sec == second + 1 ? motorNow : 0;
            sonarLast = sec == second + 1 ? sonarNow : 0;
            second = sec;
            motorNow = 0;
            sonarNow = 0;
        }
        motorNow++;
        if (sonarNew) {
            sonarNow++;
        }
    }

    /** @return the states of the last whole second before the one of {@code nowMs}; 0 if that is not the latest */
    synchronized int motorPacCount(long nowMs) {
        return nowMs / 1000 == second ? motorLast : 0;
    }

    synchronized int sonarPacCount(long nowMs) {
        return nowMs / 1000 == second ? sonarLast : 0;
    }

    /** Logs a cycle's tasks that took longer than the warning time, and clears the no-warning flag. */
    void cycleTook(long nanos, String robot) {
        long ms = nanos / 1_000_000L;
        int warn = warningMs;
        if (warn > 0 && ms > warn && !noTimeWarningThisCycle) {
            LOG.warning(() -> "robot " + robot + ": ArRobot::myCycle: Warning: Cycle took " + ms
                    + " ms of wall-clock time (the cycle warning time is " + warn + " ms)");
        }
        noTimeWarningThisCycle = false;
    }
}
