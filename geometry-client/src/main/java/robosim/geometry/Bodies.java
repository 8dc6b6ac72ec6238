package robosim.geometry;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import java.util.Objects;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.Polygon;

/**
 * The moving bodies of the {@link GeometryClient}'s world, numbered by id, each with its outline
 * where it stands, kept by the cells of a uniform grid that grows when a body leaves it. Nearby
 * bodies are given in id order, as a scan of them all would give them, so the answers never
 * depend on the grid.
 */
final class Bodies {
    private final GeometryFactory factory;
    private final double cellSize;
    private final List<Body> list = new ArrayList<>();
    /** The bodies left out of every query (a puck held in a gripper). */
    private final BitSet hidden = new BitSet();
    /** The area the grid covers; null until there is an obstacle or a body. */
    private Envelope extent;
    private CellGrid grid;

    /**
     * @param extent   the area the grid covers at first (the obstacles'), or null
     * @param cellSize the side of a grid cell, mm
     * @param factory  makes the bodies' outlines
     */
    Bodies(Envelope extent, double cellSize, GeometryFactory factory) {
        this.cellSize = cellSize;
        this.factory = factory;
        if (extent != null) {
            this.extent = extent;
            grid = new CellGrid(extent, cellSize);
        }
    }

    /** @return the new body's id */
    int add(BodyShape shape, Pose2D pose) {
        Body b = new Body(shape, pose, factory);
        int id = list.size();
        list.add(b);
        if (!regrid(b.envelope)) {
            grid.add(id, b.envelope);
        }
        return id;
    }

    void move(int id, Pose2D pose) {
        place(id, new Body(list.get(id).shape, pose, factory));
    }

    void replace(int id, BodyShape shape) {
        place(id, new Body(shape, list.get(id).pose, factory));
    }

    private void place(int id, Body b) {
        list.set(id, b);
        if (!regrid(b.envelope)) {
            grid.move(id, b.envelope);
        }
    }

    void setSolid(int id, boolean solid) {
        Objects.checkIndex(id, list.size());
        hidden.set(id, !solid);
    }

    Body get(int id) {
        return list.get(id);
    }

    /**
     * @return the bodies whose envelope intersects {@code env}, but the one ignored, in the order of
     *         their ids
     */
    List<Body> near(Envelope env, int ignoreId) {
        CellGrid.Ids ids = new CellGrid.Ids();
        near(env, ignoreId, ids);
        List<Body> near = new ArrayList<>(ids.size());
        for (int k = 0; k < ids.size(); k++) {
            near.add(list.get(ids.get(k)));
        }
        return near;
    }

    /**
     * {@link #near}, as ids into a list of the caller's, which keeps its array from one query to the
     * next.
     *
     * @param env      an area
     * @param ignoreId a body left out, or -1
     * @param out      emptied, then given the ids of the bodies whose envelope intersects the area, ascending
     */
    void near(Envelope env, int ignoreId, CellGrid.Ids out) {
        out.clear();
        if (grid == null) {
            return;
        }
        grid.query(env, out);
        int n = 0;
        for (int k = 0; k < out.size(); k++) {
            int i = out.get(k);
            if (i != ignoreId && !hidden.get(i) && list.get(i).envelope.intersects(env)) {
                out.set(n++, i);
            }
        }
        out.truncate(n);
    }

    /**
     * Adds to a gathering the edges of the bodies {@link #near} would answer, body by body in the
     * same order.
     *
     * @param env      an area
     * @param ignoreId a body left out, or -1
     * @param into     the gathering, whose id list the grid's query uses
     */
    void gather(Envelope env, int ignoreId, Surroundings into) {
        if (grid == null) {
            return;
        }
        CellGrid.Ids near = into.ids;
        grid.query(env, near);
        for (int k = 0; k < near.size(); k++) {
            int i = near.get(k);
            Body b = list.get(i);
            if (i != ignoreId && !hidden.get(i) && b.envelope.intersects(env)) {
                for (Segment s : b.segments) {
                    into.add(s);
                }
            }
        }
    }

    /**
     * Grows the grid, when a body lies outside it, to about twice the size it then needs, and lists
     * every body in it again.
     *
     * @return false if the grid already covered the envelope and nothing was done
     */
    private boolean regrid(Envelope env) {
        if (grid != null && grid.covers(env)) {
            return false;
        }
        Envelope wider = new Envelope(env);
        if (extent != null) {
            wider.expandToInclude(extent);
        }
        wider.expandBy(Math.max(wider.getWidth(), wider.getHeight()) / 2 + cellSize);
        extent = wider;
        grid = new CellGrid(wider, cellSize);
        for (int i = 0; i < list.size(); i++) {
            grid.add(i, list.get(i).envelope);
        }
        return true;
    }

    /** A body where it stands: its shape, pose, outline (as a closed ring, and as a polygon), envelope and edges. */
    static final class Body {
        final BodyShape shape;
        final Pose2D pose;
        final Coordinate[] ring;
        final Polygon polygon;
        final Envelope envelope;
        final Segment[] segments;

        Body(BodyShape shape, Pose2D pose, GeometryFactory factory) {
            this.shape = shape;
            this.pose = pose;
            ring = shape.ringAt(pose);
            polygon = factory.createPolygon(ring);
            envelope = polygon.getEnvelopeInternal();
            segments = new Segment[ring.length - 1];
            for (int i = 0; i + 1 < ring.length; i++) {
                segments[i] = new Segment(ring[i].x, ring[i].y, ring[i + 1].x, ring[i + 1].y);
            }
        }
    }
}
