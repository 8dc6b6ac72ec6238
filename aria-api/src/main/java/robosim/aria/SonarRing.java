package robosim.aria;

import java.util.List;
import robosim.protocol.SonarUnit;

/**
 * A robot's sonar ring as ARIA keeps it: one {@link ArSensorReading} per transducer, updated when
 * a cycle brings readings, and ARIA's rule for the closest sonar within an angle interval.
 */
final class SonarRing {
    private final List<SonarUnit> units;
    private final ArSensorReading[] readings;

    SonarRing(List<SonarUnit> units, double maxRange) {
        this.units = units;
        this.readings = new ArSensorReading[units.size()];
        for (SonarUnit u : units) {
            readings[u.index()] = new ArSensorReading(u.x(), u.y(), u.th(), (int) maxRange);
        }
    }

    int size() {
        return readings.length;
    }

    /**
     * Takes a cycle's ranges: only the transducers that fired in it get new data, so the others keep
     * their counter and are not new ({@link ArRobot#isSonarNew}); a cycle without sonar readings (the
     * sonars are off) changes nothing.
     *
     * @param fired the {@link robosim.protocol.SonarReading#fresh() fresh} bits of the state's sonar reading:
     *              bit i for transducer i; null when all fired
     */
    void update(int[] ranges, Long fired, ArPose pose, long counter, long timeMs) {
        if (ranges.length == readings.length) {
            for (int i = 0; i < ranges.length; i++) {
                if (fired == null || i < Long.SIZE && (fired >> i & 1) != 0) {
                    readings[i].newData(ranges[i], pose, counter, timeMs);
                }
            }
        }
    }

    /** Moves every reading by a rigid motion, for {@link ArRobot#moveTo}. */
    void applyTransform(ArTransform t) {
        for (ArSensorReading r : readings) {
            r.applyTransform(t);
        }
    }

    int range(int num) {
        return num < 0 || num >= readings.length ? -1 : readings[num].getRange();
    }

    ArSensorReading reading(int num) {
        return num < 0 || num >= readings.length ? null : readings[num];
    }

    boolean isNew(int num, long counter) {
        return num >= 0 && num < readings.length && !readings[num].getIgnoreThisReading() && readings[num].isNew(counter);
    }

    /** ARIA's rule: strictly inside the wrapping interval; ties to the lowest index; −1 if none. */
    int closest(double startAngle, double endAngle) {
        int best = -1;
        for (SonarUnit u : units) {
            if (ArMath.angleBetween(u.th(), startAngle, endAngle) && (best < 0 || range(u.index()) < range(best))) {
                best = u.index();
            }
        }
        return best;
    }
}
