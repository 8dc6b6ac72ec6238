package robosim.env.sensors;

import robosim.geometry.Pose2D;
import robosim.geometry.Surroundings;
import robosim.protocol.Command;
import robosim.protocol.LaserReading;
import robosim.protocol.RobotParameters;
import robosim.protocol.StateParts;
import robosim.protocol.TruePose;

/**
 * The SICK LMS200, off until {@link Command.ConfigureLaser} switches it on: one ray per reading
 * over 180° from the parameter file's laser pose, with the world's laser noise.
 */
final class LaserSensor implements Sensor {
    private final SensorSetup setup;
    private final RobotParameters params;
    private boolean on;
    private double increment = 1;
    private double maxRange;
    private int[] scan = new int[0];
    /**
     * Each beam's unit vector, for the heading in {@link #aimedBits}: a robot that has not turned
     * since its previous scan keeps them (the same heading gives the same vectors, bit for bit), so
     * a scan's 2 sines and cosines per beam are worked out only when it turns.
     */
    private double[] beamX = new double[0];
    private double[] beamY = new double[0];
    private long aimedBits;

    LaserSensor(SensorSetup setup) {
        this.setup = setup;
        this.params = setup.params();
        this.maxRange = params.laserMaxRange();
    }

    @Override
    public boolean configures(Command.SensorSetting setting) {
        return setting instanceof Command.ConfigureLaser;
    }

    @Override
    public void configure(Command.SensorSetting setting) {
        Command.ConfigureLaser l = (Command.ConfigureLaser) setting;
        on = l.on();
        increment = l.increment();
        maxRange = l.maxRange();
        scan = new int[0];
        beamX = new double[0];
        beamY = new double[0];
    }

    @Override
    public double reach() {
        return on ? maxRange : 0;
    }

    @Override
    public void sense(SensorInput in) {
        if (!on || !in.gathers()) {
            return;
        }
        int n = (int) Math.round(180 / increment) + 1;
        if (scan.length != n) {
            scan = new int[n];
        }
        Surroundings near = in.near();
        Pose2D p = in.pose();
        double lx = p.worldX(params.laserX(), params.laserY());
        double ly = p.worldY(params.laserX(), params.laserY());
        aim(p.th(), n);
        for (int i = 0; i < n; i++) {
            double r = setup.noisy(near.rayAlong(lx, ly, beamX[i], beamY[i], maxRange), setup.noise().laserSigma());
            scan[i] = (int) Math.round(Math.max(0, Math.min(maxRange, r)));
        }
    }

    /** Points the {@code n} beams for a heading, as {@code Surroundings.ray} would turn each beam's angle. */
    private void aim(double th, int n) {
        long bits = Double.doubleToRawLongBits(th);
        if (beamX.length == n && bits == aimedBits) {
            return;
        }
        if (beamX.length != n) {
            beamX = new double[n];
            beamY = new double[n];
        }
        double base = th + Math.toRadians(params.laserTh() - 90);
        double step = Math.toRadians(increment);
        for (int i = 0; i < n; i++) {
            beamX[i] = Math.cos(base + i * step);
            beamY[i] = Math.sin(base + i * step);
        }
        aimedBits = bits;
    }

    /** @return the latest scan, mm; empty while off */
    int[] scan() {
        return on ? scan.clone() : new int[0];
    }

    /** @return degrees between readings, as last configured */
    double increment() {
        return increment;
    }

    @Override
    public StateParts report(StateParts parts, TruePose truePose) {
        return on ? parts.with(LaserReading.PART, new LaserReading(scan.clone())) : parts;
    }
}
