package robosim.env.sensors;

import robosim.geometry.Angles;
import robosim.protocol.Bumpers;
import robosim.protocol.StateParts;
import robosim.protocol.TruePose;

/**
 * The bumper ring, always on: the body's contacts in {@value Bumpers#SECTORS} sectors of 60°,
 * sector 0 centred dead ahead, felt as the robot's own motion ends (before the robots after it
 * move), as a bumper closes under the robot that pushes it.
 */
final class BumperRing implements Sensor {
    /** A body this near something touches it, mm. */
    static final double CONTACT_TOLERANCE = 1.0;

    private int sectors;

    @Override
    public void moved(Moved m) {
        int bits = 0;
        for (double a : m.geometry().contacts(m.bodyId(), CONTACT_TOLERANCE)) {
            double relative = Angles.fix(Math.toDegrees(a) - m.th());
            bits |= 1 << Math.floorMod((int) Math.floor((relative + 30) / 60), Bumpers.SECTORS);
        }
        sectors = bits;
    }

    @Override
    public StateParts report(StateParts parts, TruePose truePose) {
        return parts.with(Bumpers.PART, new Bumpers(sectors));
    }
}
