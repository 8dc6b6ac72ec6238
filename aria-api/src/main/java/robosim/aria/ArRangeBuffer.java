package robosim.aria;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;

/**
 * A bounded list of readings, newest first, as ARIA's {@code ArRangeBuffer}: adding to a full
 * buffer evicts the oldest. Not thread-safe; its {@link ArRangeDevice} guards it.
 */
final class ArRangeBuffer {
    /** The closest reading found by {@link #closestPolar}: its distance and relative angle. */
    record Closest(double distance, double angle) { }

    private final String role;
    private final Deque<ArPoseWithTime> readings = new ArrayDeque<>();
    private int size;

    /**
     * @param role what the buffer is, for messages: {@code current} or {@code cumulative}
     * @param size its capacity
     */
    ArRangeBuffer(String role, int size) {
        this.role = role;
        setSize(size);
    }

    int getSize() {
        return size;
    }

    /** A smaller size evicts the oldest readings at once. */
    void setSize(int size) {
        if (size < 0) {
            throw new IllegalArgumentException(size + " was supplied for " + role
                    + "BufferSize: a buffer size must be 0 or more");
        }
        this.size = size;
        trim();
    }

    /** Adds a reading as the newest; a buffer of size 0 keeps nothing. */
    void add(ArPoseWithTime reading) {
        readings.addFirst(reading);
        trim();
    }

    private void trim() {
        while (readings.size() > size) {
            readings.removeLast();
        }
    }

    void clear() {
        readings.clear();
    }

    /** Removes the readings strictly closer than {@code dist} to (x, y). */
    void removeWithin(double x, double y, double dist) {
        readings.removeIf(r -> r.closerThan(x, y, dist));
    }

    /**
     * ARIA's {@code addReadingConditional}'s test (ArRangeBuffer.cpp): the first reading, newest
     * first, strictly closer than {@code dist} to (x, y) gets the time {@code nowMs}, keeping its place.
     *
     * @return whether there was one
     */
    boolean refreshWithin(double x, double y, double dist, long nowMs) {
        List<ArPoseWithTime> all = new ArrayList<>(readings);
        for (int i = 0; i < all.size(); i++) {
            ArPoseWithTime r = all.get(i);
            if (r.closerThan(x, y, dist)) {
                all.set(i, new ArPoseWithTime(r.x(), r.y(), nowMs, r.robotPose()));
                readings.clear();
                readings.addAll(all);
                return true;
            }
        }
        return false;
    }

    /** @return the readings, newest first, as a new list */
    List<ArPoseWithTime> readings() {
        return new ArrayList<>(readings);
    }

    /** @return whether a reading lies strictly closer than {@code dist} to (x, y) */
    boolean anyCloserThan(double x, double y, double dist) {
        for (ArPoseWithTime r : readings) {
            if (r.closerThan(x, y, dist)) {
                return true;
            }
        }
        return false;
    }

    /** Removes the readings a rule picks. */
    void removeIf(java.util.function.Predicate<ArPoseWithTime> rule) {
        readings.removeIf(rule);
    }

    /** Removes the readings taken more than {@code maxAgeMs} before {@code nowMs}. */
    void removeOlderThan(long nowMs, long maxAgeMs) {
        readings.removeIf(r -> nowMs - r.timeMs() > maxAgeMs);
    }

    /** Removes the readings farther than {@code dist} from the robot's position. */
    void removeFartherThan(ArPose robot, double dist) {
        readings.removeIf(r -> r.fartherThan(robot.getX(), robot.getY(), dist));
    }

    /** Moves every reading by a rigid motion, as ARIA's {@code ArRangeBuffer::applyTransform}. */
    void applyTransform(ArTransform t) {
        List<ArPoseWithTime> moved = new ArrayList<>(readings.size());
        for (ArPoseWithTime r : readings) {
            moved.add(r.moved(t));
        }
        readings.clear();
        readings.addAll(moved);
    }

    /**
     * ARIA's {@code ArRangeBuffer::getClosestBox}: the reading nearest the robot centre among those
     * inside a box given in the robot's frame (x forward, y left), edges included; the corners may
     * come in any order.
     *
     * @param robot the robot's pose
     * @return the nearest reading in the robot's frame (its heading the reading's 0 turned into that
     *         frame), or null if none is in the box
     */
    ArPose closestBox(double x1, double y1, double x2, double y2, ArPose robot) {
        ArTransform toLocal = new ArTransform(robot, new ArPose());
        double minX = Math.min(x1, x2);
        double maxX = Math.max(x1, x2);
        double minY = Math.min(y1, y2);
        double maxY = Math.max(y1, y2);
        ArPose best = null;
        double bestDist = Double.POSITIVE_INFINITY;
        for (ArPoseWithTime r : readings) {
            ArPose p = toLocal.doTransform(r.toPose());
            if (p.getX() >= minX && p.getX() <= maxX && p.getY() >= minY && p.getY() <= maxY) {
                double d = Math.hypot(p.getX(), p.getY());
                if (d < bestDist) {
                    bestDist = d;
                    best = p;
                }
            }
        }
        return best;
    }

    /** @return the readings' positions, newest first, as new poses */
    List<ArPose> poses() {
        List<ArPose> out = new ArrayList<>(readings.size());
        for (ArPoseWithTime r : readings) {
            out.add(r.toPose());
        }
        return out;
    }

    /**
     * ARIA's {@code getClosestPolar}: the reading nearest the robot among those whose direction,
     * relative to the robot's heading, lies strictly inside the interval ({@link ArMath#angleBetween}).
     *
     * @param start interval start, degrees
     * @param end   interval end, degrees
     * @param robot the robot's pose
     * @return the nearest reading's distance from the robot centre and relative angle, or null
     */
    Closest closestPolar(double start, double end, ArPose robot) {
        Closest best = null;
        for (ArPoseWithTime r : readings) {
            ArPose p = r.toPose();
            double th = ArMath.subAngle(robot.findAngleTo(p), robot.getTh());
            if (ArMath.angleBetween(th, start, end)) {
                double d = robot.findDistanceTo(p);
                if (best == null || d < best.distance()) {
                    best = new Closest(d, th);
                }
            }
        }
        return best;
    }
}
