package robosim.geometry;

import java.util.ArrayList;
import java.util.List;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.geom.prep.PreparedGeometry;
import org.locationtech.jts.geom.prep.PreparedGeometryFactory;
import org.locationtech.jts.index.strtree.STRtree;

/**
 * The static obstacles as polygons, kept by the cells of a uniform grid and numbered in the order
 * of the leaves of a JTS STRtree of their envelopes ({@link StrOrder}): a query answers those whose
 * envelope intersects it in that order, as the STRtree the {@link GeometryClient} kept before did
 * (an item in a node the tree passes over cannot intersect, its envelope lying inside the node's).
 * Each polygon is prepared for repeated intersection tests when first tested, not all at once.
 *
 * <p>Where an envelope has a coordinate that is not finite the tree may pass over nodes the grid
 * would not (a bound that is not a number), or the grid has no cells to cut the area into, so such
 * obstacles are kept in an STRtree as before.
 *
 * <p>Threads: {@link #prepared} fills a cache; it must not run concurrently with itself.
 */
final class ObstacleIndex {
    private final Polygon[] polygons;
    private final PreparedGeometry[] prepared;
    private final CellGrid grid;
    /** The STRtree of the numbers, for obstacles with a coordinate that is not finite; else null. */
    private final STRtree tree;

    /**
     * @param obstacles the static walls and obstacles; empty ones are left out, as an STRtree leaves them out
     * @param extent    the area they cover ({@link ObstacleEdges#extent}), or null if there are none
     * @param cellSize  the side of a grid cell, mm
     */
    ObstacleIndex(List<Polygon> obstacles, Envelope extent, double cellSize) {
        List<Polygon> kept = new ArrayList<>(obstacles.size());
        for (Polygon p : obstacles) {
            if (!p.getEnvelopeInternal().isNull()) {
                kept.add(p);
            }
        }
        double[] boxes = boxes(kept);
        boolean numbers = true;
        for (double v : boxes) {
            numbers &= Double.isFinite(v);
        }
        int[] order = numbers ? StrOrder.leafOrder(boxes) : identity(kept.size());
        polygons = new Polygon[order.length];
        for (int i = 0; i < order.length; i++) {
            polygons[i] = kept.get(order[i]);
        }
        prepared = new PreparedGeometry[polygons.length];
        tree = numbers ? null : tree(polygons);
        grid = !numbers || polygons.length == 0 ? null : new CellGrid(extent, cellSize, polygons.length);
        for (int i = 0; grid != null && i < polygons.length; i++) {
            grid.add(i, polygons[i].getEnvelopeInternal());
        }
    }

    private static double[] boxes(List<Polygon> polygons) {
        double[] out = new double[4 * polygons.size()];
        for (int i = 0; i < polygons.size(); i++) {
            Envelope e = polygons.get(i).getEnvelopeInternal();
            out[4 * i] = e.getMinX();
            out[4 * i + 1] = e.getMinY();
            out[4 * i + 2] = e.getMaxX();
            out[4 * i + 3] = e.getMaxY();
        }
        return out;
    }

    private static int[] identity(int n) {
        int[] out = new int[n];
        for (int i = 0; i < n; i++) {
            out[i] = i;
        }
        return out;
    }

    private static STRtree tree(Polygon[] polygons) {
        STRtree tree = new STRtree();
        for (int i = 0; i < polygons.length; i++) {
            tree.insert(polygons[i].getEnvelopeInternal(), i);
        }
        tree.build();
        return tree;
    }

    /**
     * @param env an area
     * @return the numbers of the obstacles whose envelope intersects it, in the STRtree's order
     */
    int[] query(Envelope env) {
        CellGrid.Ids out = new CellGrid.Ids();
        query(env, out);
        return out.toArray();
    }

    /**
     * {@link #query(Envelope)} into a list of the caller's, which keeps its array from one query to
     * the next: what the motion queries use, several times a step for every moving robot.
     *
     * @param env an area
     * @param out emptied, then given the numbers of the obstacles whose envelope intersects it, in
     *            the STRtree's order
     */
    void query(Envelope env, CellGrid.Ids out) {
        out.clear();
        if (tree != null) {
            for (Object o : tree.query(env)) {
                out.add((Integer) o);
            }
            return;
        }
        if (grid == null) {
            return;
        }
        grid.query(env, out);
        int n = 0;
        for (int k = 0; k < out.size(); k++) {
            int i = out.get(k);
            if (polygons[i].getEnvelopeInternal().intersects(env)) {
                out.set(n++, i);
            }
        }
        out.truncate(n);
    }

    /**
     * @param i an obstacle's number
     * @return its polygon
     */
    Polygon polygon(int i) {
        return polygons[i];
    }

    /**
     * @param i an obstacle's number
     * @return its polygon, prepared for repeated intersection tests
     */
    PreparedGeometry prepared(int i) {
        PreparedGeometry p = prepared[i];
        if (p == null) {
            p = PreparedGeometryFactory.prepare(polygons[i]);
            prepared[i] = p;
        }
        return p;
    }
}
