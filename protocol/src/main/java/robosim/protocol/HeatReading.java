package robosim.protocol;

/**
 * What a heat sensor senses: the strongest heat source in its field of view.
 *
 * @param intensity the source's intensity as it arrives at the sensor (see the heat model in docs/SIMULATION.md);
 *                  0 when no source is in view
 * @param bearing   the direction to that source, degrees, relative to the robot's heading
 * @param distance  the distance from the sensor to that source, mm (0 when none is in view)
 */
public record HeatReading(double intensity, double bearing, double distance) {
    /** Its key: the heat sensor's part of a robot's state; absent (the sensor off) reads as null. */
    public static final StatePart<HeatReading> PART = StatePart.of("heat", HeatReading.class);

}
