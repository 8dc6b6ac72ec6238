package robosim.aria;

import java.util.EnumMap;
import java.util.Map;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.protocol.RobotParameters;

/**
 * {@link ArRobot}'s absolute maxima and the limits ARIA keeps beside them that RoboSim's drive has
 * no command for (the negative translational velocity limit and the lateral ones), with ARIA's
 * rules ({@code ArRobot::setAbsoluteMaxTransVel} and its kin, ArRobot.cpp): a value of 0 or less
 * (for the negative velocity, 0 or more) is refused with a log line; one beyond the top the robot
 * reports in its config packet ({@code TransVelTop} and so on) is capped to it with a log line.
 *
 * <p>The tops are what the Environment drives: the parameter file's {@code MaxVelocity} and
 * {@code MaxRVelocity}, the Environment's largest acceleration ({@link RobotParameters#MAX_ACCELERATION}),
 * and 0 for the lateral ones, as for a Pioneer, which has no lateral motion; each absolute maximum
 * starts at its top, as ARIA sets them from the config packet when it connects.
 */
final class Maxima {
    private static final Logger LOG = Logger.getLogger(ArRobot.class.getName());

    /** The absolute maxima, each with ARIA's setter and top names. */
    enum Absolute {
        TRANS_VEL("setAbsoluteMaxTransVel", "TransVelTop"),
        TRANS_NEG_VEL("setAbsoluteMaxTransNegVel", "TransVelTop"),
        TRANS_ACCEL("setAbsoluteMaxTransAccel", "TransAccelTop"),
        TRANS_DECEL("setAbsoluteMaxTransDecel", "TransAccelTop"),
        ROT_VEL("setAbsoluteMaxRotVel", "RotVelTop"),
        ROT_ACCEL("setAbsoluteMaxRotAccel", "RotAccelTop"),
        ROT_DECEL("setAbsoluteMaxRotDecel", "RotAccelTop"),
        LAT_VEL("setAbsoluteMaxLatVel", "LatVelTop"),
        LAT_ACCEL("setAbsoluteMaxLatAccel", "LatAccelTop"),
        LAT_DECEL("setAbsoluteMaxLatDecel", "LatAccelTop");

        final String setter;
        final String top;

        Absolute(String setter, String top) {
            this.setter = setter;
            this.top = top;
        }
    }

    private final Map<Absolute, Double> tops = new EnumMap<>(Absolute.class);
    private final Map<Absolute, Double> absolute = new EnumMap<>(Absolute.class);
    private double transNegVelMax;
    private double latVelMax;
    private double latAccel;
    private double latDecel;

    /** Sets the tops from the robot's parameters, and every maximum and limit to them, as when ARIA connects. */
    synchronized void reset(RobotParameters p) {
        tops.put(Absolute.TRANS_VEL, p.maxVelocity());
        tops.put(Absolute.TRANS_NEG_VEL, -p.maxVelocity());
        tops.put(Absolute.TRANS_ACCEL, RobotParameters.MAX_ACCELERATION);
        tops.put(Absolute.TRANS_DECEL, RobotParameters.MAX_ACCELERATION);
        tops.put(Absolute.ROT_VEL, p.maxRVelocity());
        tops.put(Absolute.ROT_ACCEL, RobotParameters.MAX_ACCELERATION);
        tops.put(Absolute.ROT_DECEL, RobotParameters.MAX_ACCELERATION);
        tops.put(Absolute.LAT_VEL, 0.0);
        tops.put(Absolute.LAT_ACCEL, 0.0);
        tops.put(Absolute.LAT_DECEL, 0.0);
        absolute.putAll(tops);
        transNegVelMax = -p.maxVelocity();
        latVelMax = 0;
        latAccel = 0;
        latDecel = 0;
    }

    synchronized double get(Absolute which) {
        return absolute.get(which);
    }

    /**
     * @param which the maximum
     * @param value the value given
     * @param robot the robot's name, for the log lines
     * @return the value set (capped at the top), or null when ARIA's rule refuses it
     */
    synchronized Double set(Absolute which, double value, String robot) {
        boolean negative = which == Absolute.TRANS_NEG_VEL;
        if (negative ? !(value < 0) : !(value > 0)) {
            LOG.info(() -> "robot " + robot + ": ArRobot::" + which.setter + ": given a value " + (negative ? ">=" : "<=")
                    + " 0 (" + value + ") and will not set it");
            return null;
        }
        double top = tops.get(which);
        double v = value;
        if (negative ? v < top : v > top) {
            LOG.info(() -> "robot " + robot + ": ArRobot::" + which.setter + ": given a value (" + value + ") "
                    + (negative ? "below " : "over ") + which.top + " (" + top + ") and will cap it");
            v = top;
        }
        absolute.put(which, v);
        if (negative && transNegVelMax < v) {
            transNegVelMax = v;
        } else if (which == Absolute.LAT_VEL && latVelMax > v) {
            latVelMax = v;
        } else if (which == Absolute.LAT_ACCEL && latAccel > v) {
            latAccel = v;
        } else if (which == Absolute.LAT_DECEL && latDecel > v) {
            latDecel = v;
        }
        return v;
    }

    synchronized double transNegVelMax() {
        return transNegVelMax;
    }

    /** ARIA's {@code setTransNegVelMax}: 0 or more is ignored, below the absolute maximum is capped, each with a log line. */
    synchronized void setTransNegVelMax(double negVel, String robot) {
        if (!(negVel < 0)) {
            LOG.warning(() -> "robot " + robot + ": ArRobot: setTransNegVelMax of " + negVel + " is not below 0, ignoring it");
            return;
        }
        double abs = absolute.get(Absolute.TRANS_NEG_VEL);
        if (negVel < abs) {
            LOG.warning(() -> "robot " + robot + ": ArRobot: setTransNegVelMax of " + negVel
                    + " is over the absolute max vel of " + abs + ", capping it");
        }
        transNegVelMax = Math.max(negVel, abs);
    }

    synchronized double latVelMax() {
        return latVelMax;
    }

    synchronized double latAccel() {
        return latAccel;
    }

    synchronized double latDecel() {
        return latDecel;
    }

    /**
     * ARIA's {@code setLatVelMax}, {@code setLatAccel} and {@code setLatDecel}: 0 or less is ignored,
     * over the absolute maximum is capped, each with a log line (at ARIA's verbose level, here
     * {@code FINE}, as the robot has no lateral motion).
     *
     * @param which LAT_VEL, LAT_ACCEL or LAT_DECEL
     */
    synchronized void setLateral(Absolute which, double value, String robot) {
        String name = switch (which) {
            case LAT_VEL -> "setLatVelMax";
            case LAT_ACCEL -> "setLatAccel";
            default -> "setLatDecel";
        };
        if (!(value > 0)) {
            LOG.log(Level.FINE, () -> "robot " + robot + ": ArRobot: " + name + " of " + value + " is below 0, ignoring it");
            return;
        }
        double abs = absolute.get(which);
        if (value > abs) {
            LOG.log(Level.FINE, () -> "robot " + robot + ": ArRobot: " + name + " of " + value
                    + " is over the absolute max of " + abs + ", capping it");
        }
        double v = Math.min(value, abs);
        switch (which) {
            case LAT_VEL -> latVelMax = v;
            case LAT_ACCEL -> latAccel = v;
            default -> latDecel = v;
        }
    }
}
