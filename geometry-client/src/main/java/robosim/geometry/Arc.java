package robosim.geometry;

import org.locationtech.jts.geom.Coordinate;

/**
 * A motion of constant curvature from a start pose, as a sweep follows it: the places along it of
 * one body, each a pose and the body's ring there. Each pose is the one {@link Pose2D#advance}
 * gives for that part of the motion, and each ring the one {@link BodyShape#ringAt} gives there,
 * bit for bit; but the start's sine and cosine are worked out once for the whole motion, and a ring
 * takes its heading's sine and cosine from its pose's own arithmetic. A place costs two sines and
 * cosines on a turning motion, none on a straight one; six and four before.
 */
final class Arc {
    private final BodyShape shape;
    private final Pose2D start;
    private final double distance;
    private final double rotation;
    private final double cos;
    private final double sin;

    /**
     * @param shape    the body that moves
     * @param start    where the motion starts
     * @param distance arc length of the whole motion, mm, negative backwards
     * @param rotation heading change of the whole motion, radians
     */
    Arc(BodyShape shape, Pose2D start, double distance, double rotation) {
        this.shape = shape;
        this.start = start;
        this.distance = distance;
        this.rotation = rotation;
        cos = Math.cos(start.th());
        sin = Math.sin(start.th());
    }

    /**
     * @param f the part of the motion gone, 0 to 1
     * @return the pose {@code start.advance(distance * f, rotation * f)}, and the body's ring there
     */
    Place at(double f) {
        double d = distance * f;
        double r = rotation * f;
        if (Math.abs(r) < 1e-12) {
            Pose2D pose = new Pose2D(start.x() + d * cos, start.y() + d * sin, start.th());
            return new Place(pose, shape.ringAt(pose.x(), pose.y(), cos, sin));
        }
        double radius = d / r;
        double th1 = start.th() + r;
        double sin1 = Math.sin(th1);
        double cos1 = Math.cos(th1);
        Pose2D pose = new Pose2D(start.x() + radius * (sin1 - sin), start.y() - radius * (cos1 - cos), th1);
        return new Place(pose, shape.ringAt(pose.x(), pose.y(), cos1, sin1));
    }

    /**
     * A place along the motion.
     *
     * @param pose where the body stands
     * @param ring its outline there, closed
     */
    record Place(Pose2D pose, Coordinate[] ring) {
    }
}
