package robosim.geometry;

import java.util.ArrayList;
import java.util.List;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.LineString;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.index.strtree.STRtree;

/**
 * The static obstacles' edges, kept by the cells of a uniform grid so that a query looks only at
 * the edges near it. They are numbered, and answered, in the order of the leaves of a JTS STRtree
 * of them: the order the {@link GeometryClient} looked them up in before it had grids, so the
 * answers, ties included, are the same.
 */
final class ObstacleEdges {
    private final Segment[] edges;
    private final Envelope[] envelopes;
    private final CellGrid grid;

    /**
     * @param obstacles the static walls and obstacles
     * @param extent    the area they cover ({@link #extent}), or null if there are none
     * @param cellSize  the side of a grid cell, mm
     */
    ObstacleEdges(List<Polygon> obstacles, Envelope extent, double cellSize) {
        STRtree index = new STRtree();
        for (Polygon p : obstacles) {
            addRing(index, p.getExteriorRing());
            for (int i = 0; i < p.getNumInteriorRing(); i++) {
                addRing(index, p.getInteriorRingN(i));
            }
        }
        index.build();
        // an STRtree answers a query with the leaves that meet it, in the order of its leaves
        List<?> ordered = index.query(new Envelope(Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY));
        edges = ordered.toArray(new Segment[0]);
        envelopes = new Envelope[edges.length];
        grid = edges.length == 0 ? null : new CellGrid(extent, cellSize);
        for (int i = 0; i < edges.length; i++) {
            envelopes[i] = envelope(edges[i]);
            grid.add(i, envelopes[i]);
        }
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

    private static void addRing(STRtree index, LineString ring) {
        Coordinate[] c = ring.getCoordinates();
        for (int i = 0; i + 1 < c.length; i++) {
            Segment s = new Segment(c[i].x, c[i].y, c[i + 1].x, c[i + 1].y);
            index.insert(envelope(s), s);
        }
    }

    private static Envelope envelope(Segment s) {
        return new Envelope(s.x1(), s.x2(), s.y1(), s.y2());
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
            if (envelopes[i].intersects(env)) {
                out.add(edges[i]);
            }
        }
        return out;
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
