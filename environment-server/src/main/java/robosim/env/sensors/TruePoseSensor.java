package robosim.env.sensors;

import robosim.protocol.Command;
import robosim.protocol.StateParts;
import robosim.protocol.TruePose;

/**
 * The ground truth, off until {@link Command.ReportTruePose} switches it on: each state then
 * carries where the robot truly is, as a simulator's SIMSTAT does.
 */
final class TruePoseSensor implements Sensor {
    private boolean on;

    @Override
    public boolean configures(Command.SensorSetting setting) {
        return setting instanceof Command.ReportTruePose;
    }

    @Override
    public void configure(Command.SensorSetting setting) {
        on = ((Command.ReportTruePose) setting).on();
    }

    @Override
    public StateParts report(StateParts parts, TruePose truePose) {
        return on ? parts.with(TruePose.PART, truePose) : parts;
    }
}
