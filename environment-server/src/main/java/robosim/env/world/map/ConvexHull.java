package robosim.env.world.map;

/** The convex hull of points (Andrew's monotone chain), without repeated or collinear points. */
final class ConvexHull {
    private ConvexHull() {
    }

    /**
     * @param xy x0, y0, x1, y1, ...: at least three points, not all on one line
     * @return the hull's corners x, y, counter-clockwise, starting at the lowest-x (then lowest-y) point
     */
    static double[] of(double[] xy) {
        int n = xy.length / 2;
        int[] idx = new int[n];
        for (int i = 0; i < n; i++) {
            idx[i] = i;
        }
        IndexSort.sort(idx, xy, 0);
        int[] hull = new int[2 * n];
        int k = 0;
        for (int i = 0; i < n; i++) {
            while (k >= 2 && cross(xy, hull[k - 2], hull[k - 1], idx[i]) <= 0) {
                k--;
            }
            hull[k++] = idx[i];
        }
        for (int i = n - 2, lower = k + 1; i >= 0; i--) {
            while (k >= lower && cross(xy, hull[k - 2], hull[k - 1], idx[i]) <= 0) {
                k--;
            }
            hull[k++] = idx[i];
        }
        // the last point repeats the first
        double[] ring = new double[2 * (k - 1)];
        for (int i = 0; i < k - 1; i++) {
            ring[2 * i] = xy[2 * hull[i]];
            ring[2 * i + 1] = xy[2 * hull[i] + 1];
        }
        return ring;
    }

    private static double cross(double[] xy, int o, int a, int b) {
        return (xy[2 * a] - xy[2 * o]) * (xy[2 * b + 1] - xy[2 * o + 1])
                - (xy[2 * a + 1] - xy[2 * o + 1]) * (xy[2 * b] - xy[2 * o]);
    }
}
