package robosim.env.core;

import robosim.protocol.Command;
import robosim.protocol.GripperState;

/**
 * One robot's Pioneer 2-DOF gripper as a state machine of time: the paddles close and open, the
 * lift rises and lowers, each taking a set time for its whole travel, and ARIA's GRIPPER commands
 * ({@code ArGripperCommands} in ARIA's ArGripper.h) start and stop them. Knows nothing of the
 * world: whoever steps it says whether an object stands between the paddles, and learns whether
 * the paddles closed on it or let it go.
 *
 * <p>Decided timings (the gripper's manual gives none that ARIA reads): the paddles take
 * {@value #PADDLE_TRAVEL_S} s from fully open to fully closed, the lift {@value #LIFT_TRAVEL_S} s
 * from the bottom to the top. The gripper starts deployed: paddles open, lift down. Paddles that
 * close on an object stop at its width and go on pressing (moving, in ARIA's bits) for the grasp
 * time GRIP_PRESSURE set, {@value #DEFAULT_GRASP_TIME} × 20 ms until one is set.
 */
final class GripperModel {
    /** Seconds the paddles take from fully open to fully closed. */
    static final double PADDLE_TRAVEL_S = 2.0;
    /** Seconds the lift takes from the bottom to the top. */
    static final double LIFT_TRAVEL_S = 3.0;
    /** The grasp time before a GRIP_PRESSURE, in 20 ms units. */
    static final int DEFAULT_GRASP_TIME = 10;
    /** The space between the fully open paddles, mm. */
    static final double OPEN_WIDTH = 215;

    /** What a step did with the object between the paddles. */
    enum Event {
        /** Nothing changed. */
        NONE,
        /** The paddles closed on the object: it is held. */
        GRIPPED,
        /** The paddles opened: the object held is let go. */
        RELEASED
    }

    private double paddles;
    private double lift;
    private int paddleDir;
    private int liftDir;
    /** Seconds the lift still moves for a LIFT_CARRY, or -1 when it moves to its end. */
    private double liftLeft = -1;
    /** Seconds the paddles go on pressing on the object they hold. */
    private double squeeze;
    private int graspTime = DEFAULT_GRASP_TIME;
    private boolean holding;
    private double heldRadius;

    /**
     * Starts or stops the paddles and the lift, as the gripper's firmware takes each code.
     *
     * @param c the command
     */
    void command(Command.Gripper c) {
        switch (c.op()) {
            case Command.Gripper.GRIP_OPEN -> paddleDir = -1;
            case Command.Gripper.GRIP_CLOSE -> close();
            case Command.Gripper.GRIP_STOP -> paddleDir = 0;
            case Command.Gripper.LIFT_UP -> lift(1, -1);
            case Command.Gripper.LIFT_DOWN -> lift(-1, -1);
            case Command.Gripper.LIFT_STOP -> lift(0, -1);
            case Command.Gripper.GRIPPER_STORE -> {
                close();
                lift(1, -1);
            }
            case Command.Gripper.GRIPPER_DEPLOY -> {
                paddleDir = -1;
                lift(-1, -1);
            }
            case Command.Gripper.GRIPPER_HALT -> {
                paddleDir = 0;
                lift(0, -1);
            }
            case Command.Gripper.GRIP_PRESSURE -> graspTime = c.value();
            case Command.Gripper.LIFT_CARRY -> lift(Integer.signum(c.value()), Math.abs(c.value()) * 0.020);
            default -> throw new IllegalStateException("the gripper has no rule for code " + c.op());
        }
    }

    private void close() {
        paddleDir = 1;
        squeeze = graspTime * 0.020;
    }

    private void lift(int dir, double seconds) {
        liftDir = dir;
        liftLeft = dir == 0 ? -1 : seconds;
    }

    /**
     * Moves the paddles and the lift on by one step.
     *
     * @param dt        seconds
     * @param candidate the radius of the object that stands between the paddles, free to be held,
     *                  mm; 0 for none
     * @return whether the paddles closed on the object or let go of the one they held
     */
    Event advance(double dt, double candidate) {
        advanceLift(dt);
        if (paddleDir < 0) {
            paddles = snap(paddles - dt / PADDLE_TRAVEL_S);
            if (paddles == 0) {
                paddleDir = 0;
            }
            if (holding && gap() > 2 * heldRadius) {
                holding = false;
                return Event.RELEASED;
            }
        } else if (paddleDir > 0) {
            if (holding) {
                squeeze -= dt;
                if (squeeze <= 0) {
                    paddleDir = 0;
                }
                return Event.NONE;
            }
            double next = snap(paddles + dt / PADDLE_TRAVEL_S);
            if (candidate > 0 && next >= closedOn(candidate)) {
                paddles = Math.max(paddles, closedOn(candidate));
                holding = true;
                heldRadius = candidate;
                if (squeeze <= 0) {
                    paddleDir = 0;
                }
                return Event.GRIPPED;
            }
            paddles = next;
            if (paddles == 1) {
                paddleDir = 0;
            }
        }
        return Event.NONE;
    }

    private void advanceLift(double dt) {
        if (liftDir == 0) {
            return;
        }
        double t = liftLeft >= 0 ? Math.min(dt, liftLeft) : dt;
        lift = snap(lift + liftDir * t / LIFT_TRAVEL_S);
        if (liftLeft >= 0) {
            liftLeft = liftLeft - t < END ? 0 : liftLeft - t;
        }
        if (lift == 0 || lift == 1 || liftLeft == 0) {
            lift(0, -1);
        }
    }

    /** Travel this near an end is at the end: sums of steps miss it by rounding. */
    private static final double END = 1e-9;

    /** @return the fraction of travel within 0 and 1, at an end when within {@link #END} of it */
    private static double snap(double v) {
        return v < END ? 0 : v > 1 - END ? 1 : v;
    }

    /** @return how far closed the paddles are when they touch both sides of an object of this radius */
    static double closedOn(double radius) {
        return Math.max(0, 1 - 2 * radius / OPEN_WIDTH);
    }

    /** @return the space between the paddles now, mm */
    double gap() {
        return (1 - paddles) * OPEN_WIDTH;
    }

    /** @return whether the paddles hold an object */
    boolean holding() {
        return holding;
    }

    /** @return whether the lift is at the bottom, where the paddles reach objects on the floor */
    boolean down() {
        return lift == 0;
    }

    /** Lets go of the object held without moving the paddles (the object was taken away). */
    void drop() {
        holding = false;
    }

    /**
     * @param beams  the break beams' bits ({@link GripperState#OUTER_BEAM}, {@link GripperState#INNER_BEAM})
     * @param holdIx the index of the object held, or -1
     * @return the state as ARIA's bits give it
     */
    GripperState state(int beams, int holdIx) {
        int bits = beams;
        if (paddles > 0) {
            bits |= GripperState.PADDLES_OPEN_CLEAR;
        }
        if (lift > 0 && lift < 1) {
            bits |= GripperState.LIFT_LIMIT_CLEAR;
        }
        if (!holding && paddles < 1) {
            bits |= GripperState.LEFT_PADDLE_CLEAR | GripperState.RIGHT_PADDLE_CLEAR;
        }
        if (liftDir != 0) {
            bits |= GripperState.LIFT_MOVING;
        }
        if (paddleDir != 0) {
            bits |= GripperState.PADDLES_MOVING;
        }
        return new GripperState(bits, graspTime, paddles, lift, holding ? holdIx : -1);
    }
}
