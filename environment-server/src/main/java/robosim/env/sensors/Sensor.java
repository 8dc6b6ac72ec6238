package robosim.env.sensors;

import robosim.geometry.GeometryClient;
import robosim.protocol.Command;
import robosim.protocol.StateParts;
import robosim.protocol.TruePose;

/**
 * One sensor of a simulated robot, whole: the settings it takes, what it reads, and the part it
 * adds to the robot's state. Each robot has its own instance of every sensor of
 * {@link SensorKinds#ALL}, made when the robot is; the simulation calls it in this order each step:
 * {@link #configure} for each of the robot's settings that {@link #configures} says are its own,
 * {@link #moved} once the robot has moved, {@link #sense} once every robot has moved, and
 * {@link #report} when the robot's state is made. A sensor draws its noise from the robot's own
 * seeded stream, in the order of {@link SensorKinds#ALL}, which is what keeps a run the same.
 */
public interface Sensor {
    /**
     * @param setting one of the robot's sensor settings
     * @return whether it is this sensor's
     */
    default boolean configures(Command.SensorSetting setting) {
        return false;
    }

    /**
     * Switches or configures the sensor as the setting says.
     *
     * @param setting a setting {@link #configures} took
     */
    default void configure(Command.SensorSetting setting) {
        throw new IllegalStateException(getClass().getSimpleName() + " takes no setting, not " + setting);
    }

    /**
     * @return how far from the robot it looks for walls and bodies now, mm; 0 when it needs none
     *         (off, or not a range sensor)
     */
    default double reach() {
        return 0;
    }

    /**
     * The robot has just moved, or was put somewhere: what touches the body and what the motion
     * cost are known here, before the other robots move.
     *
     * @param m the robot's motion
     */
    default void moved(Moved m) {
    }

    /**
     * Takes a reading, once every robot has moved (or, before the first step, when first asked).
     *
     * @param in what the sensor may read from
     */
    default void sense(SensorInput in) {
    }

    /**
     * @param parts    the state's parts so far
     * @param truePose where the robot truly is now
     * @return the parts with this sensor's own (none while it is off)
     */
    StateParts report(StateParts parts, TruePose truePose);

    /**
     * A robot's own motion in a step, or its placing.
     *
     * @param geometry the world, with the robot's body where it now is and the robots yet to move
     *                 where they were
     * @param bodyId   the robot's body
     * @param th       its true heading now, degrees
     * @param leftMm   how far its left wheel travelled, mm, negative backwards (0 when placed)
     * @param rightMm  how far its right wheel travelled, mm
     * @param dt       the seconds the motion took (0 when placed)
     */
    record Moved(GeometryClient geometry, int bodyId, double th, double leftMm, double rightMm, double dt) {
    }
}
