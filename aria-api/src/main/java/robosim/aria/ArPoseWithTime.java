package robosim.aria;

/**
 * One reading kept by a range device's buffer (ARIA's {@code ArPoseWithTime}, ariaUtil.h): where the
 * echo lies, in global mm, stamped with the simulated time and the robot's pose when it was added.
 * {@link ArRangeDevice#getCurrentReadings()} and {@link ArRangeDevice#getCumulativeReadings()} give
 * them; ARIA's getters {@link #getX()}, {@link #getY()}, {@link #getTh()}, {@link #getTime()} and
 * {@link #getPose()} read them.
 *
 * @param x         the echo's global x, mm
 * @param y         the echo's global y, mm
 * @param timeMs    simulated time when it was added, ms
 * @param robotPose the robot's pose when it was added
 */
public record ArPoseWithTime(double x, double y, long timeMs, ArPose robotPose) {
    /** Copies the robot's pose, which is mutable. */
    public ArPoseWithTime {
        robotPose = new ArPose(robotPose.getX(), robotPose.getY(), robotPose.getTh());
    }

    /** @return the echo's global x, mm (ARIA's {@code getX}) */
    public double getX() {
        return x;
    }

    /** @return the echo's global y, mm (ARIA's {@code getY}) */
    public double getY() {
        return y;
    }

    /** @return 0: a range reading is a point, without a heading (ARIA's {@code getTh}) */
    public double getTh() {
        return 0;
    }

    /** @return when the reading was added, in simulated time (ARIA's {@code getTime}) */
    public ArTime getTime() {
        return ArTime.ofMs(timeMs);
    }

    /** @return the echo's position as a new pose, heading 0 */
    public ArPose getPose() {
        return toPose();
    }

    /** @return the robot's pose when the reading was added, a copy */
    @Override
    public ArPose robotPose() {
        return new ArPose(robotPose);
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
