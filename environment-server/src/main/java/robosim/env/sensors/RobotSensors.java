package robosim.env.sensors;

import java.util.ArrayList;
import java.util.List;
import robosim.geometry.Surroundings;
import robosim.protocol.CameraView;
import robosim.protocol.Command;
import robosim.protocol.StateParts;
import robosim.protocol.TruePose;

/** One robot's sensors, one of each of {@link SensorKinds#ALL}, called in that order. */
public final class RobotSensors {
    private final List<Sensor> sensors;
    private final SonarSensor sonar;
    private final LaserSensor laser;
    private final CameraSensor camera;
    /** What the range sensors gather around the robot, kept from one reading to the next. */
    private final Surroundings near = new Surroundings();

    /**
     * @param setup what the robot's sensors are made from
     */
    public RobotSensors(SensorSetup setup) {
        List<Sensor> made = new ArrayList<>();
        for (var kind : SensorKinds.ALL) {
            made.add(kind.apply(setup));
        }
        this.sensors = List.copyOf(made);
        this.sonar = only(SonarSensor.class);
        this.laser = only(LaserSensor.class);
        this.camera = only(CameraSensor.class);
    }

    private <S extends Sensor> S only(Class<S> type) {
        S found = null;
        for (Sensor s : sensors) {
            if (type.isInstance(s)) {
                found = type.cast(s);
            }
        }
        return found;
    }

    /**
     * Hands a setting to the sensor whose it is.
     *
     * @param setting one of the robot's sensor settings
     * @throws IllegalStateException if no sensor takes it
     */
    public void configure(Command.SensorSetting setting) {
        for (Sensor s : sensors) {
            if (s.configures(setting)) {
                s.configure(setting);
                return;
            }
        }
        throw new IllegalStateException("no sensor takes " + setting);
    }

    /** @param m the robot's motion, or its placing */
    public void moved(Sensor.Moved m) {
        for (Sensor s : sensors) {
            s.moved(m);
        }
    }

    /**
     * Reads every sensor. A robot's sensors are read by one thread at a time (in a step, each robot
     * on one of the workers), so the surroundings they gather into are the robot's own.
     *
     * @param in what the sensors read from
     */
    public void sense(SensorInput in) {
        in.gatherInto(near);
        for (Sensor s : sensors) {
            s.sense(in);
        }
    }

    /**
     * @param parts    the state's parts so far
     * @param truePose where the robot truly is
     * @return the parts with every sensor's own
     */
    public StateParts report(StateParts parts, TruePose truePose) {
        StateParts out = parts;
        for (Sensor s : sensors) {
            out = s.report(out, truePose);
        }
        return out;
    }

    /**
     * @param bodyRadius the robot body's radius, mm
     * @return how far from the robot's centre its range sensors gather walls and bodies, mm; 0 if
     *         none is on
     */
    public double gatherRadius(double bodyRadius) {
        double reach = 0;
        for (Sensor s : sensors) {
            reach = Math.max(reach, s.reach());
        }
        return reach > 0 ? reach + bodyRadius : 0;
    }

    /** @return every sonar transducer's latest range while the ring is on, as viewers draw it; else empty */
    public int[] sonarForViewers() {
        return sonar == null || !sonar.isOn() ? new int[0] : sonar.ranges();
    }

    /** @return the laser's latest scan while it is on, as viewers draw it; else empty */
    public int[] laserForViewers() {
        return laser == null ? new int[0] : laser.scan();
    }

    /** @return the laser's degrees between readings, as last configured (1 before) */
    public double laserIncrement() {
        return laser == null ? 1 : laser.increment();
    }

    /** @return the camera's view, or null while it is off */
    public CameraView camera() {
        return camera == null ? null : camera.view();
    }
}
