package robosim.env.sensors;

import java.util.Arrays;
import robosim.geometry.Surroundings;
import robosim.protocol.Command;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarReading;
import robosim.protocol.StateParts;
import robosim.protocol.TruePose;

/**
 * The sonar ring, on from the start: each transducer of the parameter file reads the nearest echo
 * in a 30° cone (MobileSim's model), with the world's sonar noise. The ring fires whole every step,
 * or in sequence ({@link Command.SetSonarCycle}), a Pioneer's banks taking turns.
 */
final class SonarSensor implements Sensor {
    /** MobileSim's sonar model: a 30° cone. */
    static final double HALF_ANGLE = Math.toRadians(15);
    /** Nearer echoes are reported at this range, mm. */
    static final int MIN_RANGE = 100;

    private final SensorSetup setup;
    private final RobotParameters params;
    private final int[] ranges;
    private final SonarCones cones;
    private boolean on = true;
    /** The ring's firing order, or null when every transducer fires every step. */
    private SonarSequence sequence;
    /** The transducers that fired in the latest reading, or null when all did. */
    private Long fresh;

    SonarSensor(SensorSetup setup) {
        this.setup = setup;
        this.params = setup.params();
        this.ranges = new int[params.sonarUnits().size()];
        Arrays.fill(ranges, (int) params.sonarMaxRange());
        this.cones = new SonarCones(params.sonarUnits(), HALF_ANGLE);
    }

    @Override
    public boolean configures(Command.SensorSetting setting) {
        return setting instanceof Command.SetSonar || setting instanceof Command.SetSonarCycle;
    }

    @Override
    public void configure(Command.SensorSetting setting) {
        if (setting instanceof Command.SetSonar s) {
            on = s.on();
        } else if (setting instanceof Command.SetSonarCycle cycle) {
            sequence = cycle.msPerFiring() == 0 ? null
                    : new SonarSequence(cycle.msPerFiring(), params.sonarUnits().size());
            fresh = null;
        }
    }

    @Override
    public double reach() {
        return on ? params.sonarMaxRange() : 0;
    }

    @Override
    public void sense(SensorInput in) {
        if (!on || !in.gathers()) {
            return;
        }
        fresh = sequence == null ? null : sequence.fire(in.timeMs());
        long firing = fresh == null ? -1L : fresh;
        Surroundings near = in.near();
        cones.aim(in.pose());
        double max = params.sonarMaxRange();
        for (int k = 0; k < cones.size(); k++) {
            int i = cones.index(k);
            if ((firing >> i & 1) == 0) {
                continue;
            }
            double r = near.wedge(cones.apexX(k), cones.apexY(k), cones.rightX(k), cones.rightY(k),
                    cones.leftX(k), cones.leftY(k), max);
            r = setup.noisy(r, setup.noise().sonarSigma());
            ranges[i] = (int) Math.round(Math.max(MIN_RANGE, Math.min(max, r)));
        }
    }

    /** @return every transducer's latest range, mm, whether the ring is on or not */
    int[] ranges() {
        return ranges.clone();
    }

    /** @return whether the ring is on */
    boolean isOn() {
        return on;
    }

    @Override
    public StateParts report(StateParts parts, TruePose truePose) {
        return on ? parts.with(SonarReading.PART, new SonarReading(ranges.clone(), fresh)) : parts;
    }
}
