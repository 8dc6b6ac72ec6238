package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonIgnore;
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
        String shape) {

    /** A body given by its length front and rear and its width. */
    public static final String RECTANGLE = "rectangle";
    /** A round body of {@code robotRadius}. */
    public static final String ROUND = "round";

    /** The laser's range when a parameter file names none: a SICK LMS200's 8000 mm. */
    public static final double DEFAULT_LASER_MAX_RANGE = 8000;

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
