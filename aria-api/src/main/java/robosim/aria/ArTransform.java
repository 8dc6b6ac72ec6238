package robosim.aria;

/**
 * A rigid motion of the plane (ARIA's {@code ArTransform}): a rotation followed by a translation,
 * given by two poses, so that the first pose is carried onto the second. The robot uses one to turn
 * its encoder pose into the pose {@link ArRobot#getPose()} answers, and {@link ArRobot#moveTo} moves
 * range-device readings with one.
 */
public final class ArTransform {
    private final double cos;
    private final double sin;
    private final double th;
    private final double x;
    private final double y;

    /** The identity: every pose is left where it is. */
    public ArTransform() {
        this(new ArPose(), new ArPose());
    }

    /**
     * The transform that carries {@code from} onto {@code to}, as ARIA's
     * {@code ArTransform::setTransform(pose1, pose2)}.
     *
     * @param from the pose before
     * @param to   the pose after
     */
    public ArTransform(ArPose from, ArPose to) {
        th = ArMath.subAngle(to.getTh(), from.getTh());
        cos = Math.cos(Math.toRadians(th));
        sin = Math.sin(Math.toRadians(th));
        x = to.getX() - (cos * from.getX() - sin * from.getY());
        y = to.getY() - (sin * from.getX() + cos * from.getY());
    }

    /**
     * @param pose a pose
     * @return a new pose: {@code pose} moved by this transform
     */
    public ArPose doTransform(ArPose pose) {
        return new ArPose(transformX(pose.getX(), pose.getY()), transformY(pose.getX(), pose.getY()),
                pose.getTh() + th);
    }

    /**
     * @param pose a pose
     * @return a new pose: {@code pose} moved back by this transform (its inverse)
     */
    public ArPose doInvTransform(ArPose pose) {
        double dx = pose.getX() - x;
        double dy = pose.getY() - y;
        return new ArPose(cos * dx + sin * dy, -sin * dx + cos * dy, pose.getTh() - th);
    }

    /** @return the rotation, degrees */
    public double getTh() {
        return th;
    }

    double transformX(double px, double py) {
        return x + cos * px - sin * py;
    }

    double transformY(double px, double py) {
        return y + sin * px + cos * py;
    }
}
