package robosim.geometry;

import java.util.ArrayList;
import java.util.List;
import org.locationtech.jts.geom.CoordinateSequence;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.LineString;
import org.locationtech.jts.geom.Polygon;

/**
 * The static obstacles' edges, kept by the cells of a uniform grid so that a query looks only at
 * the edges near it. They are numbered, and answered, in the order of the leaves of a JTS STRtree
 * of them ({@link StrOrder}): the order the {@link GeometryClient} looked them up in before it had
 * grids, so the answers, ties included, are the same. The order is worked out on the edges'
 * coordinates in one array, and no envelope is kept per edge: a scanned map may have millions.
 */
final class ObstacleEdges {
    /** The edges, in the tree's order. */
    private final Segment[] edges;
    private final CellGrid grid;

    /**
     * @param obstacles the static walls and obstacles
     * @param extent    the area they cover ({@link #extent}), or null if there are none
     * @param cellSize  the side of a grid cell, mm
     */
    ObstacleEdges(List<Polygon> obstacles, Envelope extent, double cellSize) {
        double[] found = edges(obstacles);
        int[] order = StrOrder.leafOrder(found);
        int n = order.length;
        edges = new Segment[n];
        for (int i = 0; i < n; i++) {
            int e = 4 * order[i];
            edges[i] = new Segment(found[e], found[e + 1], found[e + 2], found[e + 3]);
        }
        found = null; // garbage before the grid is built
        grid = n == 0 ? null : new CellGrid(extent, cellSize, n);
        for (int i = 0; i < n; i++) {
            Segment s = edges[i];
            // the edge's envelope, as new Envelope(x1, x2, y1, y2) makes it
            grid.add(i, lo(s.x1(), s.x2()), lo(s.y1(), s.y2()), hi(s.x1(), s.x2()), hi(s.y1(), s.y2()));
        }
    }

    /** @return every edge of every ring, x1, y1, x2, y2 each, in the order of the rings' points */
    private static double[] edges(List<Polygon> obstacles) {
        int n = 0;
        for (Polygon p : obstacles) {
            n += edgeCount(p.getExteriorRing());
            for (int i = 0; i < p.getNumInteriorRing(); i++) {
                n += edgeCount(p.getInteriorRingN(i));
            }
        }
        double[] out = new double[4 * n];
        int at = 0;
        for (Polygon p : obstacles) {
            at = addRing(out, at, p.getExteriorRing());
            for (int i = 0; i < p.getNumInteriorRing(); i++) {
                at = addRing(out, at, p.getInteriorRingN(i));
            }
        }
        return out;
    }

    private static int edgeCount(LineString ring) {
        return Math.max(0, ring.getNumPoints() - 1);
    }

    private static int addRing(double[] out, int at, LineString ring) {
        CoordinateSequence c = ring.getCoordinateSequence();
        for (int i = 0; i + 1 < c.size(); i++) {
            out[at++] = c.getX(i);
            out[at++] = c.getY(i);
            out[at++] = c.getX(i + 1);
            out[at++] = c.getY(i + 1);
        }
        return at;
    }

    /** The lower of an edge's two values along an axis, as {@link Envelope}'s constructor picks it. */
    private static double lo(double a, double b) {
        return a < b ? a : b;
    }

    private static double hi(double a, double b) {
        return a < b ? b : a;
    }

    /** @return the area the obstacles cover, or null if there are none */
    static Envelope extent(List<Polygon> obstacles) {
        Envelope extent = null;
        for (Polygon p : obstacles) {
            if (extent == null) {
                extent = new Envelope(p.getEnvelopeInternal());
            } else {
                extent.expandToInclude(p.getEnvelopeInternal());
            }
        }
        return extent;
    }

    /**
     * @param env  an area
     * @param room how many more items the list will be given
     * @return the edges whose envelope intersects {@code env}, in the STRtree's order
     */
    List<Segment> near(Envelope env, int room) {
        if (grid == null) {
            return new ArrayList<>(room);
        }
        int[] near = grid.query(env);
        List<Segment> out = new ArrayList<>(near.length + room);
        for (int i : near) {
            if (intersects(edges[i], env)) {
                out.add(edges[i]);
            }
        }
        return out;
    }

    /**
     * Adds to a gathering the edges {@link #near} would answer, in the same order.
     *
     * @param env  an area
     * @param into the gathering, whose id list the grid's query uses
     */
    void gather(Envelope env, Surroundings into) {
        if (grid == null) {
            return;
        }
        CellGrid.Ids near = into.ids;
        grid.query(env, near);
        for (int k = 0; k < near.size(); k++) {
            Segment e = edges[near.get(k)];
            if (intersects(e, env)) {
                into.add(e);
            }
        }
    }

    /** Whether an edge's envelope intersects {@code env}, as {@link Envelope#intersects(Envelope)} answers. */
    private static boolean intersects(Segment s, Envelope env) {
        return !env.isNull() && !(env.getMinX() > hi(s.x1(), s.x2()) || env.getMaxX() < lo(s.x1(), s.x2())
                || env.getMinY() > hi(s.y1(), s.y2()) || env.getMaxY() < lo(s.y1(), s.y2()));
    }

    /**
     * The distance along a ray to the nearest edge, walking the grid's cells outward from the
     * origin and stopping at the first cell that begins beyond the nearest hit so far: a ray in a
     * scanned map with 10^5 edges looks at the few near its path, not at every edge in its box.
     * The answer is the minimum over every edge the ray meets, as a scan of all would give.
     *
     * @param ox       ray origin x, mm
     * @param oy       ray origin y, mm
     * @param dx       unit direction x
     * @param dy       unit direction y
     * @param maxRange the farthest distance looked at, mm
     * @return the distance, or {@code maxRange} if no edge is nearer
     */
    double rayRange(double ox, double oy, double dx, double dy, double maxRange) {
        if (grid == null) {
            return maxRange;
        }
        double[] best = {maxRange};
        grid.walkRay(ox, oy, dx, dy, maxRange, (ids, count, exit) -> {
            for (int i = 0; i < count; i++) {
                best[0] = Math.min(best[0], edges[ids[i]].rayHit(ox, oy, dx, dy));
            }
            // a hit in a later cell lies at or beyond this one's exit; the margin absorbs rounding
            return best[0] < exit - EXIT_MARGIN;
        });
        return best[0];
    }

    /** mm: far below any distance a sensor reports, far above the rounding of a cell's exit. */
    private static final double EXIT_MARGIN = 1e-6;
}
