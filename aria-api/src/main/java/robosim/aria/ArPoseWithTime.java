package robosim.aria;

/**
 * One reading kept by a range device's buffer (ARIA's {@code ArPoseWithTime}): where the echo lies,
 * in global mm, stamped with the simulated time and the robot's pose when it was added.
 *
 * @param x         the echo's global x, mm
 * @param y         the echo's global y, mm
 * @param timeMs    simulated time when it was added, ms
 * @param robotPose the robot's pose when it was added
 */
record ArPoseWithTime(double x, double y, long timeMs, ArPose robotPose) {
    /** Copies the robot's pose, which is mutable. */
    ArPoseWithTime {
        robotPose = new ArPose(robotPose.getX(), robotPose.getY(), robotPose.getTh());
    }

    /**
     * @param t a rigid motion
     * @return this reading moved by it, with its time and the robot's pose moved too
     */
    ArPoseWithTime moved(ArTransform t) {
        return new ArPoseWithTime(t.transformX(x, y), t.transformY(x, y), timeMs, t.doTransform(robotPose));
    }

    /** @return the echo's position, heading 0 */
    ArPose toPose() {
        return new ArPose(x, y, 0);
    }

    /**
     * @param px mm
     * @param py mm
     * @return the distance from the echo to that point, mm
     */
    double distanceTo(double px, double py) {
        return Math.hypot(px - x, py - y);
    }

    /** @return {@code distanceTo(px, py) < dist}, exactly, and mostly without {@code Math.hypot} ({@link Near}) */
    boolean closerThan(double px, double py, double dist) {
        return Near.within(px - x, py - y, dist);
    }

    /** @return {@code distanceTo(px, py) > dist}, exactly, and mostly without {@code Math.hypot} ({@link Near}) */
    boolean fartherThan(double px, double py, double dist) {
        return Near.beyond(px - x, py - y, dist);
    }
}
