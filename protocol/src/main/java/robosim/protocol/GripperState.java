package robosim.protocol;

/**
 * The state of a robot's Pioneer gripper after a step, as the gripper's switches report it to
 * ARIA (the bits ARIA's ArGripper.cpp reads from the general IO port or the gripper packet).
 *
 * <p>The bits of {@code switches}: a clear bit is a closed limit switch, as on the real gripper.
 * <ul>
 *   <li>{@link #PADDLES_OPEN_CLEAR} clear: the paddles are fully open;</li>
 *   <li>{@link #LIFT_LIMIT_CLEAR} clear: the lift is all the way up or all the way down;</li>
 *   <li>{@link #OUTER_BEAM} set: the outer break beam (at the paddles' tips) is broken;</li>
 *   <li>{@link #INNER_BEAM} set: the inner break beam (near the robot) is broken;</li>
 *   <li>{@link #LEFT_PADDLE_CLEAR} and {@link #RIGHT_PADDLE_CLEAR} clear: that paddle is triggered
 *       (pressing on an object, or fully closed);</li>
 *   <li>{@link #LIFT_MOVING} set: the lift is moving;</li>
 *   <li>{@link #PADDLES_MOVING} set: the paddles are moving.</li>
 * </ul>
 *
 * Its constructor throws IllegalArgumentException if a value is out of its range.
 *
 * @param switches  the switch byte described above, 0 to 255
 * @param graspTime the grasp time the gripper was last given (GRIP_PRESSURE), in 20 ms units, 0 to 255
 * @param paddles   how far the paddles are closed: 0 fully open, 1 fully closed
 * @param lift      how far the lift is raised: 0 at the bottom, 1 at the top
 * @param holding   the index of the world object the paddles hold, or -1
 */
public record GripperState(int switches, int graspTime, double paddles, double lift, int holding) {
    /** Its key: the gripper's part of a robot's state; absent (no gripper) reads as null. */
    public static final StatePart<GripperState> PART = StatePart.of("gripper", GripperState.class);

    /** Clear when the paddles are fully open. */
    public static final int PADDLES_OPEN_CLEAR = 1;
    /** Clear when the lift is at the top or the bottom of its travel. */
    public static final int LIFT_LIMIT_CLEAR = 1 << 1;
    /** Set when the outer break beam is broken. */
    public static final int OUTER_BEAM = 1 << 2;
    /** Set when the inner break beam is broken. */
    public static final int INNER_BEAM = 1 << 3;
    /** Clear when the left paddle is triggered. */
    public static final int LEFT_PADDLE_CLEAR = 1 << 4;
    /** Clear when the right paddle is triggered. */
    public static final int RIGHT_PADDLE_CLEAR = 1 << 5;
    /** Set while the lift moves. */
    public static final int LIFT_MOVING = 1 << 6;
    /** Set while the paddles move. */
    public static final int PADDLES_MOVING = 1 << 7;

    /** Checks the ranges. */
    public GripperState {
        if (switches < 0 || switches > 255) {
            throw new IllegalArgumentException(switches + " was supplied for the gripper switches: a byte, 0 to 255");
        }
        if (graspTime < 0 || graspTime > 255) {
            throw new IllegalArgumentException(graspTime + " was supplied for the grasp time: 0 to 255");
        }
        if (!(paddles >= 0 && paddles <= 1) || !(lift >= 0 && lift <= 1)) {
            throw new IllegalArgumentException("paddles " + paddles + " and lift " + lift
                    + " were supplied for the gripper: each from 0 to 1");
        }
        if (holding < -1) {
            throw new IllegalArgumentException(holding + " was supplied for the held object: an index or -1");
        }
    }
}
