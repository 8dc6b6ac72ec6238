package robosim.aria;

import java.util.EnumMap;
import java.util.Map;
import java.util.logging.Logger;
import robosim.protocol.Command;
import robosim.protocol.Command.DriveLimit;
import robosim.protocol.RobotParameters;

/**
 * The acceleration and deceleration limits an {@link ArRobot} program set, with ARIA's rules for
 * setting them (ARIA's {@code src/ArRobot.cpp}, {@code setTransAccel} and its kin): a value of 0 or
 * less is ignored with a log line, and one over the absolute maximum is capped to it. The absolute
 * maximum starts as the Environment's ({@link RobotParameters#MAX_ACCELERATION}), so a getter answers
 * what the drive uses, and a program may lower it ({@code ArRobot#setAbsoluteMaxTransAccel}). Until a program sets one, each limit is the parameter file's.
 */
final class DriveLimits {
    private static final Logger LOG = Logger.getLogger(ArRobot.class.getName());

    private final Map<DriveLimit, Double> set = new EnumMap<>(DriveLimit.class);

    /**
     * @param limit  which limit
     * @param params the robot's parameters, for a limit not set
     * @return the limit in force, mm/s² or deg/s²
     */
    synchronized double get(DriveLimit limit, RobotParameters params) {
        Double v = set.get(limit);
        if (v != null) {
            return v;
        }
        return switch (limit) {
            case TRANS_ACCEL -> params.transAccel();
            case TRANS_DECEL -> params.transDecel();
            case ROT_ACCEL -> params.rotAccel();
            case ROT_DECEL -> params.rotDecel();
        };
    }

    /**
     * @param limit which limit
     * @param value the value a program gave
     * @param robot the robot's name, for the log line
     * @param max   the absolute maximum ({@code ArRobot#getAbsoluteMaxTransAccel} and its kin)
     * @return the command that sets it, or null when ARIA's rule ignores the value
     */
    synchronized Command.SetDriveLimit set(DriveLimit limit, double value, String robot, double max) {
        if (!(value > 0)) {
            LOG.warning(() -> "robot " + robot + ": " + setter(limit) + " of " + value
                    + " is not above 0; ignoring it, as ARIA does");
            return null;
        }
        double v = Math.min(value, max);
        if (v < value) {
            LOG.warning(() -> "robot " + robot + ": " + setter(limit) + " of " + value + " is over the absolute maximum of "
                    + max + "; capping it, as ARIA does");
        }
        set.put(limit, v);
        return new Command.SetDriveLimit(limit, v);
    }

    /**
     * @param what  the setter's name, for the log line
     * @param value the value a program gave
     * @param robot the robot's name
     * @return whether ARIA's rule ignores a velocity limit of this value (0 or less, or not a number)
     */
    static boolean ignoresVelocity(String what, double value, String robot) {
        if (value > 0) {
            return false;
        }
        LOG.warning(() -> "robot " + robot + ": " + what + " of " + value + " is not above 0; ignoring it, as ARIA does");
        return true;
    }

    private static String setter(DriveLimit limit) {
        return switch (limit) {
            case TRANS_ACCEL -> "setTransAccel";
            case TRANS_DECEL -> "setTransDecel";
            case ROT_ACCEL -> "setRotAccel";
            case ROT_DECEL -> "setRotDecel";
        };
    }
}
