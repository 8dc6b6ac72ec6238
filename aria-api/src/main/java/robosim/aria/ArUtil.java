package robosim.aria;

import java.util.logging.Logger;
import robosim.hw.AbstractRobot;

/** ARIA's utilities that robot programs use. */
public final class ArUtil {
    private static final Logger LOG = Logger.getLogger(ArUtil.class.getName());

    private ArUtil() {
    }

    /**
     * Sleeps in simulated time: the calling robot thread yields for {@code ms} simulated
     * milliseconds, rounded up to whole steps, at least one. A thread that belongs to no robot
     * sleeps in wall-clock time. Sleeping while holding the robot's lock is an error: the robot's
     * cycle needs the lock to deliver the next step.
     *
     * @param ms milliseconds
     */
    public static void sleep(long ms) {
        AbstractRobot robot = AbstractRobot.current();
        if (robot != null && robot.isConnected()) {
            robot.sleepSimulated(ms);
            return;
        }
        LOG.fine("ArUtil.sleep outside a robot's code: sleeping in wall-clock time");
        try {
            Thread.sleep(Math.max(0, ms));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
