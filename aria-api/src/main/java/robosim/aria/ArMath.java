package robosim.aria;

/**
 * ARIA's arithmetic for robot programs: angles in degrees, distances, rounding. Each rule is ARIA's
 * as {@code ArMath} in ARIA's {@code include/Aria/ariaUtil.h} states it.
 */
public final class ArMath {
    private ArMath() {
    }

    /**
     * @param angle any angle in degrees
     * @return the same direction in (-180, 180]
     */
    public static double fixAngle(double angle) {
        if (angle > -180.0 && angle <= 180.0) {
            return angle; // what the remainder gives here too, without its cost (every pose passes here)
        }
        double a = Math.IEEEremainder(angle, 360.0);
        return a <= -180.0 ? a + 360.0 : a;
    }

    /**
     * @param ang1 degrees
     * @param ang2 degrees
     * @return {@code fixAngle(ang1 + ang2)}, in (-180, 180]
     */
    public static double addAngle(double ang1, double ang2) {
        return fixAngle(ang1 + ang2);
    }

    /**
     * @param ang1 degrees
     * @param ang2 degrees
     * @return {@code fixAngle(ang1 - ang2)}
     */
    public static double subAngle(double ang1, double ang2) {
        return fixAngle(ang1 - ang2);
    }

    /**
     * ARIA's interval rule for robot-relative angles: with start &lt; end, strictly between them;
     * with start &gt; end, the interval wraps through 180°; equal bounds match nothing.
     *
     * @param th    the angle tested, degrees
     * @param start the interval's start, degrees (normalised here)
     * @param end   the interval's end, degrees (normalised here)
     * @return whether {@code th} lies strictly inside
     */
    public static boolean angleBetween(double th, double start, double end) {
        double s = fixAngle(start);
        double e = fixAngle(end);
        double t = fixAngle(th);
        if (s < e) {
            return t > s && t < e;
        }
        if (s > e) {
            return t > s || t < e;
        }
        return false;
    }

    /**
     * @param deg an angle in degrees
     * @return the angle in radians
     */
    public static double degToRad(double deg) {
        return deg * Math.PI / 180.0;
    }

    /**
     * @param rad an angle in radians
     * @return the angle in degrees
     */
    public static double radToDeg(double rad) {
        return rad * 180.0 / Math.PI;
    }

    /**
     * @param x1 the first point's x
     * @param y1 the first point's y
     * @param x2 the second point's x
     * @param y2 the second point's y
     * @return the straight-line distance between the two points
     */
    public static double distanceBetween(double x1, double y1, double x2, double y2) {
        return Math.hypot(x1 - x2, y1 - y2);
    }

    /**
     * ARIA's rounding: 0.49 is added and the result floored, so that a value just under one half
     * goes down and one half itself goes down too ({@code roundInt(2.5)} is 2, {@code roundInt(-2.5)}
     * is -3, {@code roundInt(0.51)} is 1); the result is held within an int's range. Programs that
     * turn readings into whole millimetres rely on this rule.
     *
     * @param val a value
     * @return the int ARIA rounds it to; 0 for NaN
     */
    public static int roundInt(double val) {
        double v = Math.floor(val + 0.49);
        if (Double.isNaN(v)) {
            return 0;
        }
        return v >= Integer.MAX_VALUE ? Integer.MAX_VALUE : v <= Integer.MIN_VALUE ? Integer.MIN_VALUE : (int) v;
    }
}
