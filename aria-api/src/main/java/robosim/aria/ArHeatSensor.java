package robosim.aria;

import robosim.protocol.Command;
import robosim.protocol.HeatReading;
import robosim.protocol.RobotState;

/**
 * A heat sensor (a RoboSim addition; real Pioneers have none): it senses the strongest heat source
 * in its field of view, centred on the robot's heading, out to its range. A source of intensity
 * I is felt as I·(1000/d)², d its distance in mm (at least 250 mm); walls and obstacles block
 * heat, robots do not. See the heat model in docs/SIMULATION.md.
 *
 * <pre>{@code
 * ArHeatSensor heat = new ArHeatSensor(90, 6000);
 * heat.attach(robot);            // switched on with the next step's requests
 * ...
 * if (heat.getIntensity() > 1) robot.setDeltaHeading(heat.getBearing());
 * }</pre>
 */
public final class ArHeatSensor {
    /** What switches the sensor on: its record checks the field of view and range. */
    private final Command.ConfigureHeatSensor switchOn;
    private volatile ArRobot robot;

    /**
     * @param fieldOfView degrees, from above 0 to 360
     * @param maxRange    mm, greater than 0
     * @throws IllegalArgumentException if either breaks the heat sensor's rules (those of
     *                                  {@link Command.ConfigureHeatSensor})
     */
    public ArHeatSensor(double fieldOfView, double maxRange) {
        this.switchOn = new Command.ConfigureHeatSensor(true, fieldOfView, maxRange);
    }

    /**
     * Mounts the sensor on a robot and switches it on.
     *
     * @param robot the robot
     */
    public void attach(ArRobot robot) {
        this.robot = robot;
        robot.send(switchOn);
    }

    /** Switches the sensor off and takes it off its robot. */
    public void detach() {
        ArRobot r = robot;
        if (r != null) {
            r.send(new Command.ConfigureHeatSensor(false, switchOn.fieldOfView(), switchOn.maxRange()));
            robot = null;
        }
    }

    private HeatReading reading() {
        ArRobot r = robot;
        RobotState s = r == null ? null : r.currentState();
        HeatReading h = s == null ? null : s.get(HeatReading.PART);
        return h == null ? new HeatReading(0, 0, 0) : h;
    }

    /** @return whether a source is in view (its felt intensity is above 0) */
    public boolean senses() {
        return reading().intensity() > 0;
    }

    /** @return the strongest felt intensity, 0 when nothing is in view or before the first reading */
    public double getIntensity() {
        return reading().intensity();
    }

    /** @return the direction to the strongest source, degrees relative to the robot's heading */
    public double getBearing() {
        return reading().bearing();
    }

    /** @return the distance to the strongest source, mm (0 when none is in view) */
    public double getDistance() {
        return reading().distance();
    }

    /** @return the field of view, degrees */
    public double getFieldOfView() {
        return switchOn.fieldOfView();
    }

    /** @return the range, mm */
    public double getMaxRange() {
        return switchOn.maxRange();
    }
}
