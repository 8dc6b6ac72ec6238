package robosim.pioneer.server;

import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * Keeps an ARIA client's link alive while its robot's run does not step: once a cycle (the SIP
 * cycle, in real time, as a Pioneer's firmware sends its status) it lets the {@link BridgeRobot}
 * send the status of the robot standing, which the robot does only when the run has not stepped for
 * {@value BridgeRobot#STANDBY_AFTER_MS} ms or has not stepped yet. ARIA drops a robot whose status
 * has not come for 8 s, and a program may wait a long time for its run: for the Environment's
 * welcome on a busy machine, for the world's other robots, through a pause. Ends when the robot's
 * part in the run ends.
 */
final class Standby implements Runnable {
    private static final Logger LOG = Logger.getLogger(Standby.class.getName());

    private final BridgeRobot robot;

    Standby(BridgeRobot robot) {
        this.robot = robot;
    }

    @Override
    public void run() {
        long next = System.nanoTime();
        try {
            while (robot.standBy(System.nanoTime())) {
                long cycle = robot.sipCycleMs() * 1_000_000L;
                next += cycle;
                long now = System.nanoTime();
                if (next < now - cycle) {
                    next = now; // held back (a busy machine): start again from now rather than send a burst
                }
                long wait = next - now;
                if (wait > 0) {
                    Thread.sleep(wait / 1_000_000, (int) (wait % 1_000_000));
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, "robot " + robot.getName() + ": the status of the robot standing could not be sent", e);
        }
    }
}
