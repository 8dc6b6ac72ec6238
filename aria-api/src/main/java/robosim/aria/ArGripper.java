package robosim.aria;

import java.util.logging.Logger;
import robosim.protocol.Command;
import robosim.protocol.GripperState;
import robosim.protocol.RobotState;

/**
 * The Pioneer 2-DOF gripper (paddles that open and close, a lift that rises and lowers) with
 * ARIA's calls and values, as ARIA's ArGripper.h and ArGripper.cpp give them: each command sends
 * ARIA's GRIPPER code to the robot and answers whether it was sent; each getter reads the
 * gripper's switch bits from the robot's latest state.
 *
 * <p>The gripper is simulated by the Environment, for robots whose parameter file says
 * {@code HasGripper true}. As in ARIA the type starts as {@link Type#QUERYTYPE} unless given:
 * the first state of a connected robot answers the query, {@link Type#GENIO} when the robot has a
 * gripper (as a Pioneer whose gripper is on the general IO port answers it) and
 * {@link Type#NOGRIPPER} when not. With {@link Type#NOGRIPPER} or {@link Type#QUERYTYPE} the
 * getters answer as ARIA's do for them: 0 and false.
 *
 * <pre>
 * ArGripper gripper = new ArGripper(robot);
 * gripper.gripperDeploy();
 * ...
 * if (gripper.getBreakBeamState() != 0) {
 *     gripper.gripClose();
 * }
 * </pre>
 */
public class ArGripper {
    /** ARIA's {@code ArGripper::Type}: how ARIA talks to the gripper. */
    public enum Type {
        /** Finds out the type from the robot (the default). */
        QUERYTYPE,
        /** The gripper is on the general IO port. */
        GENIO,
        /** The gripper is on the user IO port. */
        USERIO,
        /** The robot sends gripper packets. */
        GRIPPAC,
        /** There is no gripper. */
        NOGRIPPER
    }

    private static final Logger LOG = Logger.getLogger(ArGripper.class.getName());

    private final ArRobot robot;
    private Type type;

    /**
     * A gripper whose type the robot's first state answers.
     *
     * @param robot the robot it is mounted on
     */
    public ArGripper(ArRobot robot) {
        this(robot, Type.QUERYTYPE);
    }

    /**
     * @param robot the robot it is mounted on
     * @param type  how to read it; {@link Type#QUERYTYPE} to ask the robot
     */
    public ArGripper(ArRobot robot, Type type) {
        this.robot = robot;
        this.type = type == null ? Type.QUERYTYPE : type;
    }

    /** @return whether the command to open the paddles fully was sent */
    public boolean gripOpen() {
        return send(Command.Gripper.GRIP_OPEN, 0);
    }

    /** @return whether the command to close the paddles fully was sent */
    public boolean gripClose() {
        return send(Command.Gripper.GRIP_CLOSE, 0);
    }

    /** @return whether the command to stop the paddles where they are was sent */
    public boolean gripStop() {
        return send(Command.Gripper.GRIP_STOP, 0);
    }

    /** @return whether the command to raise the lift to the top was sent */
    public boolean liftUp() {
        return send(Command.Gripper.LIFT_UP, 0);
    }

    /** @return whether the command to lower the lift to the bottom was sent */
    public boolean liftDown() {
        return send(Command.Gripper.LIFT_DOWN, 0);
    }

    /** @return whether the command to stop the lift was sent */
    public boolean liftStop() {
        return send(Command.Gripper.LIFT_STOP, 0);
    }

    /** @return whether the command to store the gripper (paddles closed, lift up) was sent */
    public boolean gripperStore() {
        return send(Command.Gripper.GRIPPER_STORE, 0);
    }

    /** @return whether the command to deploy the gripper (paddles open, lift down) was sent */
    public boolean gripperDeploy() {
        return send(Command.Gripper.GRIPPER_DEPLOY, 0);
    }

    /** @return whether the command to halt the paddles and the lift was sent */
    public boolean gripperHalt() {
        return send(Command.Gripper.GRIPPER_HALT, 0);
    }

    /**
     * Sets how long the paddles go on pressing after they first grasp an object.
     *
     * @param mSecIntervals the time in 20 ms units, 0 to 255
     * @return whether the command was sent (false for a value out of range, which is logged)
     */
    public boolean gripPressure(int mSecIntervals) {
        return send(Command.Gripper.GRIP_PRESSURE, mSecIntervals);
    }

    /**
     * Moves the lift for a time.
     *
     * @param mSecIntervals the time in 20 ms units, positive to raise, negative to lower
     * @return whether the command was sent (false for a value beyond 16 bits, which is logged)
     */
    public boolean liftCarry(int mSecIntervals) {
        return send(Command.Gripper.LIFT_CARRY, mSecIntervals);
    }

    /** @return true if the paddles are moving */
    public boolean isGripMoving() {
        int d = switches();
        return d >= 0 && (d & GripperState.PADDLES_MOVING) != 0;
    }

    /** @return true if the lift is moving */
    public boolean isLiftMoving() {
        int d = switches();
        return d >= 0 && (d & GripperState.LIFT_MOVING) != 0;
    }

    /**
     * @return 0 if the paddles are between open and closed, 1 if they are open, 2 if they are
     *         closed (both paddles triggered: closed fully or on an object)
     */
    public int getGripState() {
        int d = switches();
        if (d < 0) {
            return 0;
        }
        if ((d & GripperState.LEFT_PADDLE_CLEAR) == 0 && (d & GripperState.RIGHT_PADDLE_CLEAR) == 0) {
            return 2;
        }
        return (d & GripperState.PADDLES_OPEN_CLEAR) == 0 ? 1 : 0;
    }

    /** @return 0 if no paddle is triggered, 1 if the left one is, 2 if the right one is, 3 if both are */
    public int getPaddleState() {
        int d = switches();
        if (d < 0) {
            return 0;
        }
        return ((d & GripperState.LEFT_PADDLE_CLEAR) == 0 ? 1 : 0) + ((d & GripperState.RIGHT_PADDLE_CLEAR) == 0 ? 2 : 0);
    }

    /** @return 0 if no break beam is broken, 1 if the inner one is, 2 if the outer one is, 3 if both are */
    public int getBreakBeamState() {
        int d = switches();
        if (d < 0) {
            return 0;
        }
        return ((d & GripperState.INNER_BEAM) != 0 ? 1 : 0) + ((d & GripperState.OUTER_BEAM) != 0 ? 2 : 0);
    }

    /** @return true if the lift is all the way up or all the way down, false if it is between */
    public boolean isLiftMaxed() {
        int d = switches();
        return d >= 0 && (d & GripperState.LIFT_LIMIT_CLEAR) == 0;
    }

    /** @return the type: after a query is answered, {@link Type#GENIO} or {@link Type#NOGRIPPER} */
    public Type getType() {
        if (type == Type.QUERYTYPE && robot != null && robot.isConnected()) {
            RobotState s = robot.currentState();
            if (s != null && s.step() > 0) {
                type = s.get(GripperState.PART) != null ? Type.GENIO : Type.NOGRIPPER;
                // ARIA's packetHandler's lines (ArGripper.cpp)
                ArLog.log(ArLog.Normal, type == Type.GENIO ? "Gripper:  querried, using General IO."
                        : "Gripper:  querried, the robot has no gripper.");
            }
        }
        return type;
    }

    /**
     * Sets the type; {@link Type#QUERYTYPE} asks the robot again.
     *
     * @param type the type
     */
    public void setType(Type type) {
        this.type = type == null ? Type.QUERYTYPE : type;
    }

    /** @return the number of 20 ms intervals the paddles go on pressing after they grasp an object */
    public int getGraspTime() {
        GripperState g = gripper();
        return g == null ? 0 : g.graspTime();
    }

    /**
     * Logs the gripper's state as ARIA's {@code logState} (ArGripper.cpp) does: through {@link ArLog}
     * at {@link ArLog#Terse}.
     *
     * @return the line logged
     */
    public String logState() {
        String text = stateLine();
        ArLog.log(ArLog.Terse, "%s", text);
        return text;
    }

    /**
     * As in ARIA's {@code logState}, the paddles' word takes {@code _moving} when the lift moves
     * (ARIA reads {@code isLiftMoving()} once for both).
     *
     * @return the line {@link #logState} logs, for example
     *         {@code "Lift:           maxed  Grip:          closed  BreakBeam:      inner"}, without logging it
     */
    public String stateLine() {
        Type t = getType();
        if (t == Type.NOGRIPPER) {
            return "There is no gripper.";
        }
        if (t == Type.QUERYTYPE) {
            return "Querying gripper type.";
        }
        boolean moving = isLiftMoving();
        String lift = (isLiftMaxed() ? "maxed" : "between") + (moving ? "_moving" : "");
        String grip = switch (getGripState()) {
            case 1 -> "open";
            case 2 -> "closed";
            default -> "between";
        } + (moving ? "_moving" : "");
        String beams = switch (getBreakBeamState()) {
            case 1 -> "inner";
            case 2 -> "outter";
            case 3 -> "both";
            default -> "none";
        };
        return String.format("Lift: %15s  Grip: %15s  BreakBeam: %10s", lift, grip, beams);
    }

    /** @return the robot's gripper state, or null when it has none or the type says not to read it */
    private GripperState gripper() {
        Type t = getType();
        if (t == Type.NOGRIPPER || t == Type.QUERYTYPE || robot == null) {
            return null;
        }
        RobotState s = robot.currentState();
        return s == null ? null : s.get(GripperState.PART);
    }

    /** @return the switch byte, or -1 when there is nothing to read */
    private int switches() {
        GripperState g = gripper();
        return g == null ? -1 : g.switches();
    }

    private boolean send(int op, int value) {
        if (robot == null || !robot.isConnected()) {
            return false;
        }
        Command.Gripper c;
        try {
            c = new Command.Gripper(op, value);
        } catch (IllegalArgumentException e) {
            LOG.warning(() -> "robot " + robot.getName() + "'s gripper: " + e.getMessage());
            return false;
        }
        robot.send(c);
        return true;
    }
}
