package robosim.aria;

import java.util.List;

/**
 * How a laser's scan enters its cumulative buffer, by the rules of ARIA's {@code ArLaser.cpp}
 * ({@code internalProcessReading}) with the defaults ARIA's SICK LMS200 driver sets
 * ({@code ArLMS2xx.cpp}): a reading that hit something within the maximum insert distance
 * ({@value #DEFAULT_MAX_INSERT_DIST} mm from the laser) is added unless a cumulative reading lies
 * closer than the device's minimum distance between cumulative readings; and once every
 * {@value #DEFAULT_CLEAN_INTERVAL_MS} ms of simulated time every beam of the scan, hit or not,
 * clears the cumulative readings it passes through: those whose perpendicular foot on the segment
 * from the robot to the beam's end is closer than {@value #DEFAULT_CLEAN_DIST} mm to them and farther
 * than {@value #CLEAN_KEEP_NEAR_END} mm from the beam's end (so a wall is not cleared by the beam
 * that sees it). Not thread-safe; its {@link ArSick} guards it.
 */
final class LaserCumulative {
    /** ARIA's LMS200 default: readings farther than this from the laser do not enter, mm. */
    static final double DEFAULT_MAX_INSERT_DIST = 3000;
    /** ARIA's LMS200 default: how close to a beam a cumulative reading is cleared, mm. */
    static final double DEFAULT_CLEAN_DIST = 75;
    /** ARIA's LMS200 default: how often the beams clear the cumulative buffer, ms. */
    static final long DEFAULT_CLEAN_INTERVAL_MS = 1000;
    /** ARIA's fixed margin: readings this close to a beam's end are never cleared by it, mm. */
    static final double CLEAN_KEEP_NEAR_END = 50;

    double cleanDist = DEFAULT_CLEAN_DIST;
    long cleanIntervalMs = DEFAULT_CLEAN_INTERVAL_MS;
    private Long lastCleanMs;
    /** Added to the time the interval is counted from, when it restarts (ARIA's clean offset), ms. */
    long cleanOffsetMs;

    /**
     * Takes one scan into the cumulative buffer.
     *
     * @param cumulative the buffer
     * @param scan       the scan's readings, global positions set
     * @param maxRange   readings at or beyond it hit nothing, mm
     * @param maxInsertDist how far from the laser a reading may be to go in, mm (1 or less: any)
     * @param minDist    the device's minimum distance between cumulative readings, mm (0 or less: none)
     * @param robot      the robot's pose when the scan was taken
     * @param timeMs     the scan's simulated time
     */
    void take(ArRangeBuffer cumulative, List<ArSensorReading> scan, double maxRange, double maxInsertDist,
              double minDist, ArPose robot, long timeMs) {
        if (cumulative.getSize() == 0 || scan.isEmpty()) {
            return;
        }
        boolean clean = cleanDue(timeMs) && cleanDist >= 1;
        for (ArSensorReading r : scan) {
            double x = r.getX();
            double y = r.getY();
            boolean add = r.getRange() < maxRange && (maxInsertDist <= 1 || r.getRange() <= maxInsertDist);
            if (add && minDist > 0 && cumulative.anyCloserThan(x, y, minDist)) {
                add = false;
            }
            if (clean) {
                cumulative.removeIf(c -> crossedByBeam(c, x, y, robot));
            }
            if (add) {
                cumulative.add(new ArPoseWithTime(x, y, timeMs, robot));
            }
        }
    }

    /** Counts the interval from the next scan, as ARIA's {@code resetLastCumulativeCleanTime} counts it from now. */
    void restartCleanInterval() {
        lastCleanMs = null;
    }

    /** ARIA cleans when more than the interval has passed since the last clean (or the first scan). */
    private boolean cleanDue(long timeMs) {
        if (lastCleanMs == null) {
            lastCleanMs = timeMs + cleanOffsetMs;
        }
        if (cleanIntervalMs <= 0 || timeMs - lastCleanMs > cleanIntervalMs) {
            lastCleanMs = timeMs;
            return true;
        }
        return false;
    }

    private boolean crossedByBeam(ArPoseWithTime c, double endX, double endY, ArPose robot) {
        double dx = robot.getX() - endX;
        double dy = robot.getY() - endY;
        double len2 = dx * dx + dy * dy;
        if (len2 == 0) {
            return false;
        }
        double t = ((c.x() - endX) * dx + (c.y() - endY) * dy) / len2;
        if (t < 0 || t > 1) {
            return false;
        }
        double footX = endX + t * dx;
        double footY = endY + t * dy;
        return c.closerThan(footX, footY, cleanDist)
                && Near.beyond(footX - endX, footY - endY, CLEAN_KEEP_NEAR_END);
    }
}
