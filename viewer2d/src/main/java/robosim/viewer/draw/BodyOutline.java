package robosim.viewer.draw;

import robosim.protocol.RobotParameters;

/**
 * How a robot's body is drawn, the same way in every view: the rectangle of its parameters, or a
 * disc of its radius for a round robot (and when the parameters give no rectangle).
 */
public final class BodyOutline {
    /** The radius drawn for a robot whose parameters give no size, mm. */
    public static final double FALLBACK_RADIUS_MM = 200;

    private BodyOutline() {
    }

    /**
     * @param p a robot's parameters, or null
     * @return whether its body is drawn as a rectangle
     */
    public static boolean isRectangle(RobotParameters p) {
        return p != null && !p.isRound() && p.robotWidth() > 0 && p.robotLengthFront() + p.robotLengthRear() > 0;
    }

    /**
     * @param p a robot's parameters, or null
     * @return the radius its disc is drawn with, mm
     */
    public static double radius(RobotParameters p) {
        if (p == null) {
            return FALLBACK_RADIUS_MM;
        }
        if (p.robotRadius() > 0) {
            return p.robotRadius();
        }
        double r = Math.hypot(Math.max(p.robotLengthFront(), p.robotLengthRear()), p.robotWidth() / 2);
        return r > 0 ? r : FALLBACK_RADIUS_MM;
    }

    /**
     * @param p a robot's parameters, or null
     * @return how far ahead of the centre the body reaches, mm (where the heading line ends)
     */
    public static double front(RobotParameters p) {
        return isRectangle(p) ? p.robotLengthFront() : radius(p);
    }
}
