package robosim.geometry;

/** A straight edge of an obstacle or body, in world mm. */
record Segment(double x1, double y1, double x2, double y2) {

    /** @return the distance from a point to the nearest point of this segment */
    double distanceTo(double x, double y) {
        double ex = x2 - x1;
        double ey = y2 - y1;
        double len2 = ex * ex + ey * ey;
        double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((x - x1) * ex + (y - y1) * ey) / len2));
        double px = x1 + t * ex - x;
        double py = y1 + t * ey - y;
        return Math.sqrt(px * px + py * py);
    }

    /**
     * Distance along a ray to this segment.
     *
     * @return the distance, or {@link Double#POSITIVE_INFINITY} if the ray misses
     */
    double rayHit(double ox, double oy, double dx, double dy) {
        return rayHit(x1, y1, x2 - x1, y2 - y1, ox, oy, dx, dy);
    }

    /**
     * Distance along a ray to the segment from (x1, y1) to (x1 + ex, y1 + ey).
     *
     * @return the distance, or {@link Double#POSITIVE_INFINITY} if the ray misses
     */
    static double rayHit(double x1, double y1, double ex, double ey, double ox, double oy, double dx, double dy) {
        double denom = dx * ey - dy * ex;
        double wx = x1 - ox;
        double wy = y1 - oy;
        if (Math.abs(denom) < 1e-12) {
            return Double.POSITIVE_INFINITY;
        }
        double t = (wx * ey - wy * ex) / denom;
        double u = (wx * dy - wy * dx) / denom;
        if (t < 0 || u < 0 || u > 1) {
            return Double.POSITIVE_INFINITY;
        }
        return t;
    }

    /**
     * The distance from an apex to the nearest point of this segment inside a wedge: the part of
     * the segment between the wedge's right edge (unit vector r) and left edge (unit vector l),
     * which must be less than 180° apart.
     *
     * @return the distance, or {@link Double#POSITIVE_INFINITY} if no part of the segment is inside
     */
    double wedgeDistance(double ox, double oy, double rx, double ry, double lx, double ly) {
        return wedgeDistance(x1, y1, x2 - x1, y2 - y1, ox, oy, rx, ry, lx, ly);
    }

    /**
     * {@link #wedgeDistance(double, double, double, double, double, double)} of the segment from
     * (x1, y1) to (x1 + ex, y1 + ey).
     *
     * @return the distance, or {@link Double#POSITIVE_INFINITY} if no part of the segment is inside
     */
    static double wedgeDistance(double x1, double y1, double ex, double ey, double ox, double oy,
                                double rx, double ry, double lx, double ly) {
        double ax = x1 - ox;
        double ay = y1 - oy;
        double lo = 0;
        double hi = 1;
        // inside: cross(r, p) >= 0 and cross(p, l) >= 0, with p = a + t e, each linear in t
        double c0 = rx * ay - ry * ax;
        double c1 = rx * ey - ry * ex;
        if (Math.abs(c1) < 1e-15) {
            if (c0 < 0) {
                return Double.POSITIVE_INFINITY;
            }
        } else {
            double t = -c0 / c1;
            if (c1 > 0) {
                lo = Math.max(lo, t);
            } else {
                hi = Math.min(hi, t);
            }
        }
        c0 = ax * ly - ay * lx;
        c1 = ex * ly - ey * lx;
        if (Math.abs(c1) < 1e-15) {
            if (c0 < 0) {
                return Double.POSITIVE_INFINITY;
            }
        } else {
            double t = -c0 / c1;
            if (c1 > 0) {
                lo = Math.max(lo, t);
            } else {
                hi = Math.min(hi, t);
            }
        }
        if (lo > hi) {
            return Double.POSITIVE_INFINITY;
        }
        // nearest point of the clipped part to the apex
        double len2 = ex * ex + ey * ey;
        double t = len2 == 0 ? lo : -(ax * ex + ay * ey) / len2;
        t = Math.max(lo, Math.min(hi, t));
        double px = ax + t * ex;
        double py = ay + t * ey;
        return Math.sqrt(px * px + py * py);
    }
}
