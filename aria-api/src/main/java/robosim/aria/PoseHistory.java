package robosim.aria;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Iterator;

/**
 * The latest poses of one of {@link ArRobot}'s frames with the simulated time of each, and ARIA's
 * {@code ArInterpolation::getPose} answers over them: 1 when the time falls between two readings
 * (interpolated), 0 when it is after the newest and within ARIA's default prediction allowance
 * (predicted from the two newest readings, at most 50 times their interval ahead: ARIA's 5000 %),
 * −1 when it is further ahead, −2 when it is before the oldest reading kept, −3 when there are not
 * enough readings. ARIA keeps 100 readings by default.
 */
final class PoseHistory {
    /** ARIA's default number of readings, and its default prediction allowance in percent. */
    static final int DEFAULT_READINGS = 100;
    private static final int ALLOWED_PERCENT = 5000;

    private record Reading(ArPose pose, long timeMs) { }

    /** Newest first. */
    private final Deque<Reading> readings = new ArrayDeque<>();
    private int size = DEFAULT_READINGS;

    synchronized void add(ArPose pose, long timeMs) {
        readings.addFirst(new Reading(pose, timeMs));
        trim();
    }

    synchronized void setSize(int n) {
        size = Math.max(0, n);
        trim();
    }

    synchronized int size() {
        return size;
    }

    private void trim() {
        while (readings.size() > size) {
            readings.removeLast();
        }
    }

    /**
     * @param timeMs the simulated time wanted
     * @param out    set to the pose at that time, when the answer is 0 or 1
     * @return ARIA's answer: 1, 0, −1, −2 or −3 (see the class)
     */
    synchronized int pose(long timeMs, ArPose out) {
        if (readings.isEmpty()) {
            return -3;
        }
        Iterator<Reading> it = readings.iterator();
        Reading newer = it.next();
        if (timeMs == newer.timeMs()) {
            out.setPose(newer.pose().getX(), newer.pose().getY(), newer.pose().getTh());
            return 1;
        }
        if (timeMs > newer.timeMs()) {
            if (!it.hasNext()) {
                return -3;
            }
            Reading older = it.next();
            long total = newer.timeMs() - older.timeMs();
            double fraction = (double) (timeMs - newer.timeMs()) / (total == 0 ? 100 : total);
            if (fraction * 100 > ALLOWED_PERCENT) {
                return -1;
            }
            between(newer.pose(), older.pose(), -fraction, out);
            return 0;
        }
        while (it.hasNext()) {
            Reading older = it.next();
            if (timeMs >= older.timeMs()) {
                long total = newer.timeMs() - older.timeMs();
                double fraction = total == 0 ? 0 : (double) (newer.timeMs() - timeMs) / total;
                between(newer.pose(), older.pose(), fraction, out);
                return 1;
            }
            newer = older;
        }
        return -2;
    }

    /** {@code out} = a + (b − a) · f, the heading along the shorter way round. */
    private static void between(ArPose a, ArPose b, double f, ArPose out) {
        out.setPose(a.getX() + (b.getX() - a.getX()) * f, a.getY() + (b.getY() - a.getY()) * f,
                ArMath.addAngle(a.getTh(), ArMath.subAngle(b.getTh(), a.getTh()) * f));
    }
}
