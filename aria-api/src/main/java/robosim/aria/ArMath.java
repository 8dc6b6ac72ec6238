package robosim.aria;

/** ARIA's angle arithmetic, in degrees. */
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
}
