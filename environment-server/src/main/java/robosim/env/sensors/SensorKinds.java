package robosim.env.sensors;

import java.util.List;
import java.util.function.Function;

/**
 * The sensors every simulated robot has, each made from the robot's {@link SensorSetup} (those that
 * need nothing of it ignore it): the one
 * place a sensor is registered with the simulation. The order is the order they read in, and so the
 * order they draw noise from the robot's stream: a new sensor goes at the end, or runs change.
 */
public final class SensorKinds {
    /** Every sensor, in reading order. */
    public static final List<Function<SensorSetup, Sensor>> ALL = List.of(
            SonarSensor::new,
            LaserSensor::new,
            setup -> new HeatSensor(),
            setup -> new BumperRing(),
            setup -> new TruePoseSensor(),
            setup -> new CameraSensor(),
            setup -> new BatterySensor());

    private SensorKinds() {
    }
}
