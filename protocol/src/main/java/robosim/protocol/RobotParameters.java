package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonIgnore;
import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.annotation.JsonSetter;
import com.fasterxml.jackson.annotation.Nulls;
import java.util.List;

/**
 * A robot's physical parameters, as read from its parameter file and sent to the Environment
 * when the robot connects, so that the body, limits and sensor poses the simulation uses are the
 * robot's own.
 *
 * <p>Units are ARIA's: mm, mm/s, mm/s², degrees, degrees/s, degrees/s².
 *
 * @param robotClass       the robot's class, for example {@code Pioneer}
 * @param subclass         the robot's subclass, for example {@code p3dx}
 * @param robotRadius      radius of the circle that encloses the robot
 * @param robotWidth       body width (y extent)
 * @param robotLengthFront body extent ahead of the centre of rotation
 * @param robotLengthRear  body extent behind the centre of rotation
 * @param maxVelocity      absolute maximum translational speed
 * @param maxRVelocity     absolute maximum rotational speed
 * @param transAccel       translational acceleration
 * @param transDecel       translational deceleration
 * @param rotAccel         rotational acceleration
 * @param rotDecel         rotational deceleration
 * @param diffConvFactor   ARIA's factor: the rotation is (right − left) / 2 · diffConvFactor rad/s
 * @param sonarMaxRange    the sonars' maximum range
 * @param sonarUnits       the sonar transducers, ordered by index
 * @param laserX           the laser's mounting position, mm forward of the centre
 * @param laserY           the laser's mounting position, mm left of the centre
 * @param laserTh          the laser's mounting heading, degrees
 * @param laserMaxRange    the laser's maximum range, mm (a SICK LMS200: 8000)
 * @param shape            the body: {@value #RECTANGLE} (length front and rear, width) or
 *                         {@value #ROUND} (a disc of {@code robotRadius}, as the Nomadic Scout)
 * @param hasGripper       whether a Pioneer 2-DOF gripper is mounted at the front (the parameter
 *                         file's {@code HasGripper}; left off the wire when false, and absent reads as none)
 */
public record RobotParameters(
        String robotClass,
        String subclass,
        double robotRadius,
        double robotWidth,
        double robotLengthFront,
        double robotLengthRear,
        double maxVelocity,
        double maxRVelocity,
        double transAccel,
        double transDecel,
        double rotAccel,
        double rotDecel,
        double diffConvFactor,
        double sonarMaxRange,
        List<SonarUnit> sonarUnits,
        double laserX,
        double laserY,
        double laserTh,
        double laserMaxRange,
        String shape,
        @JsonSetter(nulls = Nulls.AS_EMPTY) @JsonInclude(JsonInclude.Include.NON_DEFAULT) boolean hasGripper) {

    /** A body given by its length front and rear and its width. */
    public static final String RECTANGLE = "rectangle";
    /** A round body of {@code robotRadius}. */
    public static final String ROUND = "round";

    /** The laser's range when a parameter file names none: a SICK LMS200's 8000 mm. */
    public static final double DEFAULT_LASER_MAX_RANGE = 8000;

    /** The longest body size or mounting offset the Environment accepts, mm. */
    public static final double MAX_SIZE = 5000;
    /**
     * The smallest body and sensor range, mm: a robot's radius, width and length (front and rear
     * together), and a sensor's range when it has one. Smaller is no robot a sensor or a collision
     * could tell from a point, and only invites degenerate geometry.
     */
    public static final double MIN_SIZE = 1;
    /** The fastest translational speed the Environment accepts, mm/s. */
    public static final double MAX_SPEED = 10_000;
    /** The fastest rotational speed the Environment accepts, degrees/s. */
    public static final double MAX_ROTATION = 3600;
    /** The largest acceleration or deceleration the Environment accepts, mm/s² or degrees/s². */
    public static final double MAX_ACCELERATION = 100_000;
    /** The longest sensor range the Environment accepts, mm. */
    public static final double MAX_RANGE = 100_000;
    /** The most sonar transducers the Environment accepts. */
    public static final int MAX_SONARS = 64;
    /** The longest robot class or subclass name the Environment accepts. */
    public static final int MAX_NAME = 100;

    /**
     * Checks the values against physical bounds, as the Environment does with every robot's hello
     * before it simulates the robot: every number finite; the body's radius and width at least
     * {@value #MIN_SIZE} mm, its lengths 0 or more (a rectangle's front and rear together at least
     * {@value #MIN_SIZE} mm), all at most {@value #MAX_SIZE} mm; speeds above 0, at most
     * {@value #MAX_SPEED} mm/s and {@value #MAX_ROTATION} °/s; accelerations and decelerations 0
     * or more and at most {@value #MAX_ACCELERATION}; {@code diffConvFactor} above 0 and at most 1;
     * sensor ranges 0 (the sonar's only: none) or from {@value #MIN_SIZE} mm, and at most
     * {@value #MAX_RANGE} mm; at most
     * {@value #MAX_SONARS} sonars, each numbered by its place, and every mounting offset within
     * {@value #MAX_SIZE} mm and heading within ±360°; a known shape; names of at most
     * {@value #MAX_NAME} characters.
     *
     * @return the first value that breaks a bound, as "VALUE was supplied for FIELD: RULE", or
     *         null if all hold
     */
    public String violation() {
        String v = firstOf(
                name("robotClass", robotClass), name("subclass", subclass),
                size("robotRadius", robotRadius, false),
                size("robotWidth", robotWidth, false),
                within("robotLengthFront", robotLengthFront, true, MAX_SIZE, "mm"),
                within("robotLengthRear", robotLengthRear, true, MAX_SIZE, "mm"),
                length(),
                within("maxVelocity", maxVelocity, false, MAX_SPEED, "mm/s"),
                within("maxRVelocity", maxRVelocity, false, MAX_ROTATION, "degrees/s"),
                within("transAccel", transAccel, true, MAX_ACCELERATION, "mm/s²"),
                within("transDecel", transDecel, true, MAX_ACCELERATION, "mm/s²"),
                within("rotAccel", rotAccel, true, MAX_ACCELERATION, "degrees/s²"),
                within("rotDecel", rotDecel, true, MAX_ACCELERATION, "degrees/s²"),
                within("diffConvFactor", diffConvFactor, false, 1, ""),
                range("sonarMaxRange", sonarMaxRange, true),
                offset("laserX", laserX), offset("laserY", laserY), heading("laserTh", laserTh),
                range("laserMaxRange", laserMaxRange, false));
        if (v != null) {
            return v;
        }
        if (!RECTANGLE.equals(shape) && !ROUND.equals(shape)) {
            return "'" + shape + "' was supplied for shape: it is " + RECTANGLE + " or " + ROUND;
        }
        if (sonarUnits.size() > MAX_SONARS) {
            return sonarUnits.size() + " sonars were supplied: a robot has at most " + MAX_SONARS;
        }
        for (int i = 0; i < sonarUnits.size(); i++) {
            SonarUnit u = sonarUnits.get(i);
            String field = "sonar " + i;
            v = u.index() != i ? u.index() + " was supplied for " + field + "'s index: sonars are numbered 0, 1, ... in order"
                    : firstOf(offset(field + " x", u.x()), offset(field + " y", u.y()), heading(field + " th", u.th()));
            if (v != null) {
                return v;
            }
        }
        return null;
    }

    private static String firstOf(String... violations) {
        for (String v : violations) {
            if (v != null) {
                return v;
            }
        }
        return null;
    }

    private static String within(String field, double value, boolean zeroAllowed, double max, String unit) {
        String u = unit.isEmpty() ? "" : " " + unit;
        if (!Double.isFinite(value) || value < 0 || value == 0 && !zeroAllowed || value > max) {
            return value + " was supplied for " + field + ": it must be a finite number " + (zeroAllowed ? "from 0" : "above 0")
                    + " to " + max + u;
        }
        return null;
    }

    /** A body's size: at least {@value #MIN_SIZE} mm and at most {@value #MAX_SIZE} mm. */
    private static String size(String field, double value, boolean zeroAllowed) {
        return atLeast(field, value, zeroAllowed, MAX_SIZE);
    }

    /** A sensor's range: 0 (none) where allowed, else at least {@value #MIN_SIZE} mm, at most {@value #MAX_RANGE} mm. */
    private static String range(String field, double value, boolean zeroAllowed) {
        return atLeast(field, value, zeroAllowed, MAX_RANGE);
    }

    private static String atLeast(String field, double value, boolean zeroAllowed, double max) {
        boolean none = value == 0 && zeroAllowed;
        if (!Double.isFinite(value) || !none && (value < MIN_SIZE || value > max)) {
            return value + " was supplied for " + field + ": it must be " + (zeroAllowed ? "0 or " : "") + "from "
                    + MIN_SIZE + " to " + max + " mm";
        }
        return null;
    }

    /** A rectangular body is at least {@value #MIN_SIZE} mm long, front and rear together. */
    private String length() {
        double length = robotLengthFront + robotLengthRear;
        if (RECTANGLE.equals(shape) && Double.isFinite(length) && length < MIN_SIZE) {
            return length + " was supplied for robotLengthFront + robotLengthRear: a rectangular body is at least "
                    + MIN_SIZE + " mm long";
        }
        return null;
    }

    private static String offset(String field, double value) {
        if (!Double.isFinite(value) || Math.abs(value) > MAX_SIZE) {
            return value + " was supplied for " + field + ": it must be a finite number within ±" + MAX_SIZE + " mm";
        }
        return null;
    }

    private static String heading(String field, double value) {
        if (!Double.isFinite(value) || Math.abs(value) > 360) {
            return value + " was supplied for " + field + ": it must be a finite number within ±360 degrees";
        }
        return null;
    }

    private static String name(String field, String value) {
        if (value != null && value.length() > MAX_NAME) {
            return "a name of " + value.length() + " characters was supplied for " + field + ": at most " + MAX_NAME;
        }
        return null;
    }

    /** Copies the sonar list so the record stays immutable; a missing shape is a rectangle. */
    public RobotParameters {
        sonarUnits = List.copyOf(sonarUnits);
        shape = shape == null ? RECTANGLE : shape;
    }

    /**
     * Rectangular-bodied parameters with a laser pose.
     *
     * @param robotClass       the robot's class
     * @param subclass         the robot's subclass
     * @param robotRadius      enclosing radius
     * @param robotWidth       body width
     * @param robotLengthFront body extent ahead of the centre
     * @param robotLengthRear  body extent behind the centre
     * @param maxVelocity      maximum translational speed
     * @param maxRVelocity     maximum rotational speed
     * @param transAccel       translational acceleration
     * @param transDecel       translational deceleration
     * @param rotAccel         rotational acceleration
     * @param rotDecel         rotational deceleration
     * @param diffConvFactor   ARIA's wheel factor
     * @param sonarMaxRange    the sonars' maximum range
     * @param sonarUnits       the sonar transducers
     * @param laserX           laser x, mm
     * @param laserY           laser y, mm
     * @param laserTh          laser heading, degrees
     * @param laserMaxRange    laser range, mm
     */
    public RobotParameters(String robotClass, String subclass, double robotRadius, double robotWidth,
                           double robotLengthFront, double robotLengthRear, double maxVelocity,
                           double maxRVelocity, double transAccel, double transDecel, double rotAccel,
                           double rotDecel, double diffConvFactor, double sonarMaxRange,
                           List<SonarUnit> sonarUnits, double laserX, double laserY, double laserTh,
                           double laserMaxRange) {
        this(robotClass, subclass, robotRadius, robotWidth, robotLengthFront, robotLengthRear, maxVelocity,
                maxRVelocity, transAccel, transDecel, rotAccel, rotDecel, diffConvFactor, sonarMaxRange,
                sonarUnits, laserX, laserY, laserTh, laserMaxRange, RECTANGLE);
    }

    /**
     * Parameters without a gripper.
     *
     * @param robotClass       the robot's class
     * @param subclass         the robot's subclass
     * @param robotRadius      enclosing radius
     * @param robotWidth       body width
     * @param robotLengthFront body extent ahead of the centre
     * @param robotLengthRear  body extent behind the centre
     * @param maxVelocity      maximum translational speed
     * @param maxRVelocity     maximum rotational speed
     * @param transAccel       translational acceleration
     * @param transDecel       translational deceleration
     * @param rotAccel         rotational acceleration
     * @param rotDecel         rotational deceleration
     * @param diffConvFactor   rad/s per mm/s of wheel-speed difference
     * @param sonarMaxRange    the sonars' maximum range
     * @param sonarUnits       the sonar transducers
     * @param laserX           the laser's position, mm forward of the centre
     * @param laserY           the laser's position, mm left of the centre
     * @param laserTh          the laser's heading, degrees
     * @param laserMaxRange    the laser's maximum range, mm
     * @param shape            {@value #RECTANGLE} or {@value #ROUND}
     */
    public RobotParameters(String robotClass, String subclass, double robotRadius, double robotWidth,
                           double robotLengthFront, double robotLengthRear, double maxVelocity,
                           double maxRVelocity, double transAccel, double transDecel, double rotAccel,
                           double rotDecel, double diffConvFactor, double sonarMaxRange,
                           List<SonarUnit> sonarUnits, double laserX, double laserY, double laserTh,
                           double laserMaxRange, String shape) {
        this(robotClass, subclass, robotRadius, robotWidth, robotLengthFront, robotLengthRear, maxVelocity,
                maxRVelocity, transAccel, transDecel, rotAccel, rotDecel, diffConvFactor, sonarMaxRange,
                sonarUnits, laserX, laserY, laserTh, laserMaxRange, shape, false);
    }

    /**
     * @param has whether a gripper is mounted
     * @return these parameters with or without a gripper
     */
    public RobotParameters withGripper(boolean has) {
        return new RobotParameters(robotClass, subclass, robotRadius, robotWidth, robotLengthFront, robotLengthRear,
                maxVelocity, maxRVelocity, transAccel, transDecel, rotAccel, rotDecel, diffConvFactor, sonarMaxRange,
                sonarUnits, laserX, laserY, laserTh, laserMaxRange, shape, has);
    }

    /** @return whether the body is round */
    @JsonIgnore
    public boolean isRound() {
        return ROUND.equals(shape);
    }

    /**
     * Parameters with the laser at the centre, facing forward, with its default range.
     *
     * @param robotClass       the robot's class
     * @param subclass         the robot's subclass
     * @param robotRadius      enclosing radius
     * @param robotWidth       body width
     * @param robotLengthFront body extent ahead of the centre
     * @param robotLengthRear  body extent behind the centre
     * @param maxVelocity      maximum translational speed
     * @param maxRVelocity     maximum rotational speed
     * @param transAccel       translational acceleration
     * @param transDecel       translational deceleration
     * @param rotAccel         rotational acceleration
     * @param rotDecel         rotational deceleration
     * @param diffConvFactor   rad/s per mm/s of wheel-speed difference
     * @param sonarMaxRange    the sonars' maximum range
     * @param sonarUnits       the sonar transducers
     */
    public RobotParameters(String robotClass, String subclass, double robotRadius, double robotWidth,
                           double robotLengthFront, double robotLengthRear, double maxVelocity,
                           double maxRVelocity, double transAccel, double transDecel, double rotAccel,
                           double rotDecel, double diffConvFactor, double sonarMaxRange,
                           List<SonarUnit> sonarUnits) {
        this(robotClass, subclass, robotRadius, robotWidth, robotLengthFront, robotLengthRear, maxVelocity,
                maxRVelocity, transAccel, transDecel, rotAccel, rotDecel, diffConvFactor, sonarMaxRange,
                sonarUnits, 0, 0, 0, DEFAULT_LASER_MAX_RANGE, RECTANGLE);
    }

    /** @return the body length, front plus rear */
    public double robotLength() {
        return robotLengthFront + robotLengthRear;
    }

    /** @return the distance between the wheels implied by {@link #diffConvFactor()} */
    public double wheelBase() {
        return 2.0 / diffConvFactor;
    }
}
