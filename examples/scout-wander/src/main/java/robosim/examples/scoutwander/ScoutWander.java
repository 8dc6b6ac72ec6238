package robosim.examples.scoutwander;

import static robosim.scout.StateVector.STATE_BUMPER;
import static robosim.scout.StateVector.STATE_SONAR_0;

import robosim.scout.Scout;

/**
 * A Scout that wanders and keeps off the walls with its sonar ring, written in the Nomad client
 * library's style: each {@code gs()} brings the next step's state vector; it drives ahead with
 * {@code scout_vm} while the front is clear, steers away from a near side wall, turns in place
 * towards the more open side when something is ahead, and backs off with {@code pr} when a bumper
 * touches.
 *
 * <p>Run it as {@code bin/robosim robot robosim.examples.scoutwander.ScoutWander NAME HOST PORT [PARAMFILE]}.
 */
public final class ScoutWander {
    /** Cruising speed, 1/10 inch/s (about 350 mm/s). */
    static final int CRUISE = 140;
    /** Turning rate in place, 1/10 degree/s. */
    static final int TURN = 400;
    /** Steering away from a side wall, 1/10 degree/s. */
    static final int STEER = 120;
    /** Something nearer than this ahead, inches, makes the Scout turn in place. */
    static final long FRONT_STOP = 28;
    /** A side wall nearer than this, inches, makes the Scout steer away. */
    static final long SIDE_NEAR = 18;
    private static final int[] FRONT = {15, 0, 1};
    private static final int[] LEFT = {2, 3, 4};
    private static final int[] RIGHT = {12, 13, 14};

    private final Scout scout;
    private int turnDirection;
    private int backingOff;

    /** @param scout a connected Scout */
    public ScoutWander(Scout scout) {
        this.scout = scout;
    }

    /**
     * Runs a wandering Scout until the Environment ends the run.
     *
     * @param args NAME HOST PORT [PARAMFILE], as the original's robot applications
     */
    public static void main(String[] args) {
        if (args.length < 3) {
            throw new IllegalArgumentException("usage: ScoutWander NAME HOST PORT [PARAMFILE]");
        }
        Scout scout = new Scout(args[0], args[1], Integer.parseInt(args[2]),
                args.length > 3 ? args[3] : Scout.DEFAULT_PARAMETERS);
        if (!scout.connect_robot()) {
            throw new IllegalStateException("robot " + args[0] + " could not connect: " + scout.getConnectionError());
        }
        new ScoutWander(scout).run();
        scout.disconnect_robot();
    }

    /** Wanders, one decision per step, until the robot is disconnected. */
    public void run() {
        scout.conf_sn(1, new int[] {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15});
        scout.conf_tm(2);
        scout.tk("wandering");
        while (scout.gs()) {
            decide();
        }
    }

    /** One step's decision from the state vector. */
    void decide() {
        if (scout.State[STATE_BUMPER] != 0 && backingOff == 0) {
            backingOff = 10;
            scout.pr(-100, -100, 0); // 10 inches straight back
            return;
        }
        if (backingOff > 0) {
            backingOff--;
            return;
        }
        long front = closest(FRONT);
        long left = closest(LEFT);
        long right = closest(RIGHT);
        if (front < FRONT_STOP) {
            if (turnDirection == 0) {
                turnDirection = left >= right ? 1 : -1;
            }
            scout.scout_vm(0, TURN * turnDirection);
            return;
        }
        turnDirection = 0;
        int speed = front < 2 * FRONT_STOP ? CRUISE / 2 : CRUISE;
        if (left < SIDE_NEAR && left < right) {
            scout.scout_vm(speed, -STEER);
        } else if (right < SIDE_NEAR) {
            scout.scout_vm(speed, STEER);
        } else {
            scout.scout_vm(speed, 0);
        }
    }

    private long closest(int[] sonars) {
        long min = Long.MAX_VALUE;
        for (int s : sonars) {
            min = Math.min(min, scout.State[STATE_SONAR_0 + s]);
        }
        return min;
    }
}
