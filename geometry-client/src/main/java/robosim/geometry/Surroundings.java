package robosim.geometry;

import java.util.Arrays;
import java.util.List;

/**
 * The edges near one point, gathered once so that many range queries from around that point (a
 * ring of sonars, a laser scan) do not each search the whole world. Answers exactly as
 * {@link GeometryClient#rayRange} and {@link GeometryClient#coneRange} would for sensors within
 * the gathered radius.
 *
 * <p>Surroundings may be gathered into again ({@link GeometryClient#gather}), reusing their arrays;
 * they must not be read by one thread while another gathers into them.
 */
public final class Surroundings {
    /**
     * How far outside a cone or off a ray an edge must lie, beyond its own half length, to be
     * passed over without computing its range, mm: far above the rounding of either computation, so
     * an edge passed over is one whose range would have come out infinite.
     */
    private static final double SKIP_MARGIN = 1e-3;
    /** The rounding of coordinates grows with their size: this much per mm of coordinate. */
    private static final double SKIP_MARGIN_PER_MM = 1e-9;

    /** The numbers {@link #table} keeps of an edge, at these places of its row. */
    private static final int NEAREST = 0;
    private static final int MID_X = 1;
    private static final int MID_Y = 2;
    private static final int SLACK = 3;
    private static final int X1 = 4;
    private static final int Y1 = 5;
    private static final int EX = 6;
    private static final int EY = 7;
    private static final int ROW = 8;

    private double cx;
    private double cy;
    private int size;
    /** The edges as they were found, and each one's distance from the centre. */
    private Segment[] found = new Segment[0];
    private double[] keys = new double[0];
    /** The edges, nearest the centre first. */
    private Segment[] segments = new Segment[0];
    /**
     * A row of {@value #ROW} numbers per edge, in the order of {@link #segments}: its distance from
     * the centre (ascending), its midpoint, its half length plus the margin for rounding, its first
     * point and its vector to the second. In one array, in the order a query reads them, so an
     * edge's numbers lie together in memory.
     */
    private double[] table = new double[0];
    private final DistanceOrder order = new DistanceOrder();
    /** Room for the ids a grid query answers while gathering. */
    final CellGrid.Ids ids = new CellGrid.Ids();

    /**
     * Empty surroundings, to gather into with {@link GeometryClient#gather}, again and again: they
     * keep their arrays, so a robot's sensors gathering into their own each step allocate nothing
     * once the arrays have grown to the most edges met.
     */
    public Surroundings() {
    }

    /** Gathers {@code found}: sorts the edges by their distance from the centre, so a query can stop early. */
    Surroundings(double cx, double cy, List<Segment> found) {
        begin(cx, cy);
        for (Segment e : found) {
            add(e);
        }
        finish();
    }

    /** Starts gathering again, about a new centre, forgetting the edges gathered before. */
    void begin(double cx, double cy) {
        this.cx = cx;
        this.cy = cy;
        size = 0;
    }

    /** Adds an edge found; edges at equal distances keep the order they are added in. */
    void add(Segment e) {
        if (size == found.length) {
            int room = Math.max(16, 2 * size);
            found = Arrays.copyOf(found, room);
            keys = Arrays.copyOf(keys, room);
        }
        found[size] = e;
        keys[size] = e.distanceTo(cx, cy);
        size++;
    }

    /** Puts the edges added in order of their distance from the centre, ready for queries. */
    void finish() {
        int n = size;
        int[] byDistance = order.sort(keys, n);
        if (segments.length < n) {
            segments = new Segment[found.length];
            table = new double[ROW * found.length];
        }
        for (int i = 0; i < n; i++) {
            Segment e = found[byDistance[i]];
            segments[i] = e;
            int t = ROW * i;
            double ex = e.x2() - e.x1();
            double ey = e.y2() - e.y1();
            table[t + NEAREST] = keys[byDistance[i]];
            table[t + MID_X] = (e.x1() + e.x2()) / 2;
            table[t + MID_Y] = (e.y1() + e.y2()) / 2;
            table[t + SLACK] = Math.sqrt(ex * ex + ey * ey) / 2 + SKIP_MARGIN
                    + SKIP_MARGIN_PER_MM * (Math.abs(e.x1()) + Math.abs(e.y1()) + Math.abs(e.x2()) + Math.abs(e.y2()));
            table[t + X1] = e.x1();
            table[t + Y1] = e.y1();
            table[t + EX] = ex;
            table[t + EY] = ey;
        }
    }

    /** @return the edges gathered, nearest the centre first (equal distances in the order found) */
    List<Segment> edges() {
        return List.of(Arrays.copyOf(segments, size));
    }

    /** @return the number of edges gathered */
    public int size() {
        return size;
    }

    /**
     * The distance along a ray to the first edge it meets.
     *
     * @param x        ray origin x, mm
     * @param y        ray origin y, mm
     * @param th       direction, radians
     * @param maxRange farthest distance looked at, mm
     * @return the distance, or {@code maxRange} if nothing is nearer
     */
    public double ray(double x, double y, double th, double maxRange) {
        return rayAlong(x, y, Math.cos(th), Math.sin(th), maxRange);
    }

    /**
     * {@link #ray} with the direction given as a unit vector, so that a sensor whose rays keep their
     * directions from one reading to the next (a robot that has not turned) need not work out their
     * sines and cosines again.
     *
     * @param x        ray origin x, mm
     * @param y        ray origin y, mm
     * @param dx       x of the unit vector along the ray: {@code cos(th)}
     * @param dy       its y: {@code sin(th)}
     * @param maxRange farthest distance looked at, mm
     * @return the distance, or {@code maxRange} if nothing is nearer
     */
    public double rayAlong(double x, double y, double dx, double dy, double maxRange) {
        double best = maxRange;
        double offset = Math.sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy));
        double apexSlack = SKIP_MARGIN_PER_MM * (Math.abs(x) + Math.abs(y));
        double[] t = table;
        for (int r = 0; r < ROW * size; r += ROW) {
            // no edge farther from the centre can be hit nearer than this
            if (t[r + NEAREST] - offset > best) {
                break;
            }
            // an edge wholly to one side of the ray's line, or behind its origin, is missed
            double ax = t[r + MID_X] - x;
            double ay = t[r + MID_Y] - y;
            double off = t[r + SLACK] + apexSlack;
            double side = dx * ay - dy * ax;
            if (side > off || side < -off || dx * ax + dy * ay < -off) {
                continue;
            }
            best = Math.min(best, Segment.rayHit(t[r + X1], t[r + Y1], t[r + EX], t[r + EY], x, y, dx, dy));
        }
        return best;
    }

    /**
     * The distance to the nearest edge inside a cone (see {@link GeometryClient#coneRange}).
     *
     * @param x         apex x, mm
     * @param y         apex y, mm
     * @param th        cone axis, radians
     * @param halfAngle half the cone's opening, radians, below π/2
     * @param maxRange  farthest distance looked at, mm
     * @return the distance, or {@code maxRange} if nothing is nearer
     */
    public double cone(double x, double y, double th, double halfAngle, double maxRange) {
        return wedge(x, y, Math.cos(th - halfAngle), Math.sin(th - halfAngle),
                Math.cos(th + halfAngle), Math.sin(th + halfAngle), maxRange);
    }

    /**
     * {@link #cone} with the cone's edges given as unit vectors, so that a sensor whose cones keep
     * their directions from one reading to the next (a robot that has not turned) need not work
     * out their sines and cosines again.
     *
     * @param x        apex x, mm
     * @param y        apex y, mm
     * @param rx       x of the unit vector along the cone's right edge: {@code cos(th - halfAngle)}
     * @param ry       its y: {@code sin(th - halfAngle)}
     * @param lx       x of the unit vector along its left edge: {@code cos(th + halfAngle)}
     * @param ly       its y: {@code sin(th + halfAngle)}
     * @param maxRange farthest distance looked at, mm
     * @return the distance, or {@code maxRange} if nothing is nearer
     */
    public double wedge(double x, double y, double rx, double ry, double lx, double ly, double maxRange) {
        double best = maxRange;
        double offset = Math.sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy));
        double apexSlack = SKIP_MARGIN_PER_MM * (Math.abs(x) + Math.abs(y));
        double[] t = table;
        for (int r = 0; r < ROW * size; r += ROW) {
            // no edge farther from the centre can be nearer the apex than this one
            if (t[r + NEAREST] - offset > best) {
                break;
            }
            // an edge wholly outside either side of the wedge has no part inside it
            double ax = t[r + MID_X] - x;
            double ay = t[r + MID_Y] - y;
            double off = -(t[r + SLACK] + apexSlack);
            if (rx * ay - ry * ax < off || ax * ly - ay * lx < off) {
                continue;
            }
            best = Math.min(best, Segment.wedgeDistance(t[r + X1], t[r + Y1], t[r + EX], t[r + EY], x, y, rx, ry, lx, ly));
        }
        return best;
    }
}
