package robosim.env.core;

import java.util.List;
import java.util.random.RandomGenerator;
import robosim.env.camera.RobotCamera;
import robosim.env.world.HeatSource;
import robosim.env.world.Noise;
import robosim.geometry.GeometryClient;
import robosim.geometry.Pose2D;
import robosim.geometry.Surroundings;
import robosim.protocol.Command;
import robosim.protocol.HeatReading;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

/**
 * One robot's sensors as the Environment computes them from the robot's true pose: the sonar ring
 * (a 30° cone per transducer, MobileSim's model), the SICK laser (one ray per reading over 180°),
 * and the heat sensor. Range noise, when the world has any, is Gaussian and drawn from the robot's
 * own seeded stream.
 */
final class Sensors {
    /** MobileSim's sonar model: a 30° cone. */
    static final double SONAR_HALF_ANGLE = Math.toRadians(15);
    /** Nearer echoes are reported at this range, mm. */
    static final int SONAR_MIN_RANGE = 100;
    /** A heat source nearer than this counts as this near, mm: the sensor saturates. */
    static final double HEAT_MIN_DISTANCE = 250;

    private final RobotParameters params;
    private final Noise noise;
    private final RandomGenerator random;
    private boolean sonarOn = true;
    private final int[] sonar;
    private boolean laserOn;
    private double laserIncrement = 1;
    private double laserMaxRange;
    private int[] laser = new int[0];
    private boolean heatOn;
    private double heatFieldOfView;
    private double heatMaxRange;
    private HeatReading heat;
    /** The ring's firing order, or null when every transducer fires every step. */
    private SonarSequence sonarSequence;
    /** The transducers that fired in the latest reading, or null when all did. */
    private Long sonarNew;

    Sensors(RobotParameters params, Noise noise, RandomGenerator random) {
        this.params = params;
        this.noise = noise;
        this.random = random;
        this.sonar = new int[params.sonarUnits().size()];
        java.util.Arrays.fill(sonar, (int) params.sonarMaxRange());
        this.laserMaxRange = params.laserMaxRange();
    }

    /** The pan-tilt-zoom camera and its ACTS colour tracking, read apart as it sees other robots. */
    private final RobotCamera camera = new RobotCamera();

    /** @return the pan-tilt-zoom camera */
    RobotCamera camera() {
        return camera;
    }

    /** Whether the ground-truth sensor is on: each state carries the true pose. */
    private boolean truePoseOn;

    /** @return whether the ground-truth sensor is on */
    boolean truePoseOn() {
        return truePoseOn;
    }

    /** Switches or configures a sensor as the command says. */
    void configure(Command.SensorSetting c) {
        if (c instanceof Command.SetSonar s) {
            sonarOn = s.on();
        } else if (c instanceof Command.SetSonarCycle cycle) {
            sonarSequence = cycle.msPerFiring() == 0 ? null
                    : new SonarSequence(cycle.msPerFiring(), params.sonarUnits().size());
            sonarNew = null;
        } else if (c instanceof Command.ConfigureLaser l) {
            laserOn = l.on();
            laserIncrement = l.increment();
            laserMaxRange = l.maxRange();
            laser = new int[0];
        } else if (c instanceof Command.ConfigureHeatSensor h) {
            heatOn = h.on();
            heatFieldOfView = h.fieldOfView();
            heatMaxRange = h.maxRange();
            heat = null;
        } else if (c instanceof Command.ReportTruePose t) {
            truePoseOn = t.on();
        } else if (RobotCamera.handles(c)) {
            camera.configure(c);
        } else {
            throw new IllegalStateException("the sensors have no rule for " + c);
        }
    }

    /**
     * Takes every switched-on sensor's reading at the robot's true pose; a sonar ring that fires in
     * sequence reads only the transducers whose turn came since the previous reading.
     */
    void read(GeometryClient geometry, Pose2D pose, double bodyRadius, int bodyId, List<HeatSource> sources,
              long timeMs) {
        double radius = gatherRadius(bodyRadius);
        if (radius > 0) {
            Surroundings near = geometry.around(pose.x(), pose.y(), radius, bodyId);
            if (sonarOn) {
                sonarNew = sonarSequence == null ? null : sonarSequence.fire(timeMs);
                readSonar(near, pose, sonarNew == null ? -1L : sonarNew);
            }
            if (laserOn) {
                readLaser(near, pose);
            }
        }
        if (heatOn) {
            heat = readHeat(geometry, pose, sources);
        }
    }

    /**
     * @param bodyRadius the robot body's radius, mm
     * @return how far from the robot's centre its range sensors gather edges, mm; 0 if none is on
     */
    double gatherRadius(double bodyRadius) {
        double reach = reach();
        return reach > 0 ? reach + bodyRadius : 0;
    }

    /** @return how far the switched-on range sensors look, mm; 0 if none is on */
    double reach() {
        return Math.max(sonarOn ? params.sonarMaxRange() : 0, laserOn ? laserMaxRange : 0);
    }

    private void readSonar(Surroundings near, Pose2D p, long firing) {
        double max = params.sonarMaxRange();
        for (SonarUnit s : params.sonarUnits()) {
            if ((firing >> s.index() & 1) == 0) {
                continue;
            }
            double r = near.cone(p.worldX(s.x(), s.y()), p.worldY(s.x(), s.y()),
                    p.th() + Math.toRadians(s.th()), SONAR_HALF_ANGLE, max);
            r = noisy(r, noise.sonarSigma());
            sonar[s.index()] = (int) Math.round(Math.max(SONAR_MIN_RANGE, Math.min(max, r)));
        }
    }

    private void readLaser(Surroundings near, Pose2D p) {
        int n = (int) Math.round(180 / laserIncrement) + 1;
        if (laser.length != n) {
            laser = new int[n];
        }
        double lx = p.worldX(params.laserX(), params.laserY());
        double ly = p.worldY(params.laserX(), params.laserY());
        double base = p.th() + Math.toRadians(params.laserTh() - 90);
        double step = Math.toRadians(laserIncrement);
        for (int i = 0; i < n; i++) {
            double r = noisy(near.ray(lx, ly, base + i * step, laserMaxRange), noise.laserSigma());
            laser[i] = (int) Math.round(Math.max(0, Math.min(laserMaxRange, r)));
        }
    }

    /**
     * The strongest source in view: intensity I·(1000 / d)², d the distance in mm (at least
     * {@value #HEAT_MIN_DISTANCE}), for sources within the field of view and the maximum range
     * whose straight line to the sensor crosses no wall or obstacle.
     */
    private HeatReading readHeat(GeometryClient geometry, Pose2D p, List<HeatSource> sources) {
        HeatReading best = new HeatReading(0, 0, 0);
        for (HeatSource h : sources) {
            double d = Math.hypot(h.x() - p.x(), h.y() - p.y());
            double bearing = Angles.fix(Math.toDegrees(Math.atan2(h.y() - p.y(), h.x() - p.x()) - p.th()));
            if (d > heatMaxRange || Math.abs(bearing) > heatFieldOfView / 2
                    || !geometry.lineOfSight(p.x(), p.y(), h.x(), h.y())) {
                continue;
            }
            double felt = h.intensity() * Math.pow(1000 / Math.max(d, HEAT_MIN_DISTANCE), 2);
            if (felt > best.intensity()) {
                best = new HeatReading(felt, bearing, d);
            }
        }
        return best;
    }

    private double noisy(double range, double sigma) {
        return sigma > 0 ? range + random.nextGaussian() * sigma : range;
    }

    int[] sonar() {
        return sonarOn ? sonar.clone() : new int[0];
    }

    /** @return the transducers that fired in the latest reading, bit i for transducer i; null if all did */
    Long sonarNew() {
        return sonarOn ? sonarNew : null;
    }

    int[] laser() {
        return laserOn ? laser.clone() : new int[0];
    }

    double laserIncrement() {
        return laserIncrement;
    }

    HeatReading heat() {
        return heatOn ? heat : null;
    }
}
