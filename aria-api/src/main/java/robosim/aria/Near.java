package robosim.aria;

/**
 * Distance tests that give exactly {@code Math.hypot}'s answer, without {@code Math.hypot} (tens of
 * nanoseconds a call) when the squared distance leaves no doubt: a laser's scan tests each of its
 * 181 readings against every reading its cumulative buffer keeps, and ARIA's answers must not
 * change by a rounding. Only distances within a billionth of the bound go to {@code Math.hypot}.
 */
final class Near {
    /** How far from the bound, relatively, the squares decide alone; far above their rounding. */
    private static final double MARGIN = 1e-9;

    private Near() {
    }

    /** @return {@code Math.hypot(dx, dy) < dist} */
    static boolean within(double dx, double dy, double dist) {
        if (dist > 0) {
            double d2 = dx * dx + dy * dy;
            double below = dist * (1 - MARGIN);
            double above = dist * (1 + MARGIN);
            if (d2 < below * below) {
                return true;
            }
            if (d2 > above * above) {
                return false;
            }
        }
        return Math.hypot(dx, dy) < dist;
    }

    /** @return {@code Math.hypot(dx, dy) > dist} */
    static boolean beyond(double dx, double dy, double dist) {
        if (dist > 0) {
            double d2 = dx * dx + dy * dy;
            double below = dist * (1 - MARGIN);
            double above = dist * (1 + MARGIN);
            if (d2 > above * above) {
                return true;
            }
            if (d2 < below * below) {
                return false;
            }
        }
        return Math.hypot(dx, dy) > dist;
    }
}
