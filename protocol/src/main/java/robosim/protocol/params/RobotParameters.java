package robosim.protocol.params;

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
 * @param diffConvFactor   rad/s of rotation per mm/s of wheel-speed difference (right − left)
 * @param sonarMaxRange    the sonars' maximum range
 * @param sonarUnits       the sonar transducers, ordered by index
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
        List<SonarUnit> sonarUnits) {

    /** Copies the sonar list so the record stays immutable. */
    public RobotParameters {
        sonarUnits = List.copyOf(sonarUnits);
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
