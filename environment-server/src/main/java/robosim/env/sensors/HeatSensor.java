package robosim.env.sensors;

import robosim.env.world.HeatSource;
import robosim.geometry.Angles;
import robosim.geometry.Pose2D;
import robosim.protocol.Command;
import robosim.protocol.HeatReading;
import robosim.protocol.StateParts;
import robosim.protocol.TruePose;

/**
 * The heat sensor, off until {@link Command.ConfigureHeatSensor} switches it on: it feels the
 * strongest source in its field of view and range whose straight line to it crosses nothing.
 */
final class HeatSensor implements Sensor {
    /** A heat source nearer than this counts as this near, mm: the sensor saturates. */
    static final double MIN_DISTANCE = 250;

    private boolean on;
    private double fieldOfView;
    private double maxRange;
    private HeatReading reading;

    @Override
    public boolean configures(Command.SensorSetting setting) {
        return setting instanceof Command.ConfigureHeatSensor;
    }

    @Override
    public void configure(Command.SensorSetting setting) {
        Command.ConfigureHeatSensor h = (Command.ConfigureHeatSensor) setting;
        on = h.on();
        fieldOfView = h.fieldOfView();
        maxRange = h.maxRange();
        reading = null;
    }

    /**
     * The strongest source in view: intensity I·(1000 / d)², d the distance in mm (at least
     * {@value #MIN_DISTANCE}), for sources within the field of view and the maximum range whose
     * straight line to the sensor crosses no wall or obstacle.
     */
    @Override
    public void sense(SensorInput in) {
        if (!on) {
            return;
        }
        Pose2D p = in.pose();
        HeatReading best = new HeatReading(0, 0, 0);
        for (HeatSource h : in.heat()) {
            double d = Math.hypot(h.x() - p.x(), h.y() - p.y());
            double bearing = Angles.fix(Math.toDegrees(Math.atan2(h.y() - p.y(), h.x() - p.x()) - p.th()));
            if (d > maxRange || Math.abs(bearing) > fieldOfView / 2
                    || !in.geometry().lineOfSight(p.x(), p.y(), h.x(), h.y())) {
                continue;
            }
            double felt = h.intensity() * Math.pow(1000 / Math.max(d, MIN_DISTANCE), 2);
            if (felt > best.intensity()) {
                best = new HeatReading(felt, bearing, d);
            }
        }
        reading = best;
    }

    @Override
    public StateParts report(StateParts parts, TruePose truePose) {
        return on ? parts.with(HeatReading.PART, reading) : parts;
    }
}
