package robosim.geometry;

import java.util.ArrayList;
import java.util.List;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.operation.distance.DistanceOp;

/**
 * The world as JTS geometry: static obstacles behind spatial indexes, and the bodies of the robots,
 * which move. Answers the queries the simulation asks each step: how far a body can move before it
 * touches something (swept over the whole motion, so nothing tunnels through a thin wall), and
 * ranges along a ray and within a sonar cone.
 *
 * <p>Ranges are exact: a ray reports the nearest intersection with any edge; a cone reports the
 * nearest point of any edge that lies inside the cone's wedge (no reflections, no beam pattern).
 *
 * <p>The bodies, and the obstacles' edges, are kept by the cells of uniform grids ({@link CellGrid}),
 * so a query looks only at what is near it, and so are the obstacles' polygons ({@link ObstacleIndex}).
 * The bodies it looks at are taken in body-id order, as a scan of all bodies would; the edges and
 * the polygons in the order a JTS STRtree of them answers a query (the order of its leaves, worked
 * out by {@link StrOrder} without building one), as this class looked them up when it kept them in
 * STRtrees. The answers are the same.
 *
 * <p>Threads: the methods that change the world ({@link #addBody}, {@link #moveBody},
 * {@link #replaceBody}) must not run while any other method runs. The queries sensors use
 * ({@link #rayRange}, {@link #coneRange}, {@link #around}, {@link #lineOfSight}, {@link #bodyPose},
 * {@link #bodyPolygon}, {@link #bodyShape}) keep no scratch state, only read, and may run
 * concurrently with each other, for example one robot's sensors per thread. The motion queries
 * ({@link #overlaps}, {@link #sweep}, {@link #contacts}) keep a list of ids from one grid lookup to
 * the next, and go through JTS's prepared geometries and distance operations: they must not run
 * concurrently with each other; the simulation calls them from one thread.
 */
public final class GeometryClient {
    /** Largest heading change of one sweep piece; bounds the hull's error on arcs to about 0.1 mm. */
    private static final double MAX_PIECE_ROTATION = Math.toRadians(3);
    /** Largest length of one sweep piece of a turning motion. */
    private static final double MAX_PIECE_LENGTH = 50;
    /**
     * Most pieces of one sweep, whatever is asked: a turn of more than 360 degrees is swept once
     * (its poses repeat), so only a long turning arc reaches this, with pieces then longer than
     * {@link #MAX_PIECE_LENGTH}.
     */
    static final int MAX_PIECES = 4096;
    private static final double FULL_TURN = 2 * Math.PI;
    /** The contact search stops when the remaining gap of motion is below this, in mm. */
    private static final double CONTACT_TOLERANCE = 0.05;
    /** The side of a cell of the grids, mm: a few robots across. */
    static final double DEFAULT_CELL_SIZE = 2000;

    /** Makes the obstacles' polygons: one for all, not one each (its precision model is the default). */
    private static final GeometryFactory POLYGONS = new GeometryFactory();

    private final GeometryFactory factory = new GeometryFactory();
    private final ObstacleIndex obstacleIndex;
    private final ObstacleEdges edges;
    private final Bodies bodies;
    /**
     * The ids the motion queries' grid lookups answer into, kept from one lookup to the next: a
     * sweep makes tens of them. The motion queries run on one thread (see above).
     */
    private final CellGrid.Ids motionIds = new CellGrid.Ids();

    /**
     * @param obstacles the static walls and obstacles
     */
    public GeometryClient(List<Polygon> obstacles) {
        this(obstacles, DEFAULT_CELL_SIZE);
    }

    /**
     * @param obstacles the static walls and obstacles
     * @param cellSize  the side of a cell of the grids, mm, greater than 0
     */
    GeometryClient(List<Polygon> obstacles, double cellSize) {
        if (!(cellSize > 0) || !Double.isFinite(cellSize)) {
            throw new IllegalArgumentException(cellSize + " was supplied for cellSize: it must be greater than 0");
        }
        Envelope extent = ObstacleEdges.extent(obstacles);
        obstacleIndex = new ObstacleIndex(obstacles, extent, cellSize);
        edges = new ObstacleEdges(obstacles, extent, cellSize);
        bodies = new Bodies(extent, cellSize, factory);
    }

    /** @return the obstacles' edges whose envelope intersects {@code env}, as an STRtree of them would answer */
    List<Segment> edgesNear(Envelope env) {
        return edges.near(env, 0);
    }

    /**
     * A polygon from a flat list of coordinates.
     *
     * @param xy x0, y0, x1, y1, ... of the ring, at least three points, not closed
     * @return the polygon
     */
    public static Polygon polygon(double... xy) {
        if (xy.length < 6 || xy.length % 2 != 0) {
            throw new IllegalArgumentException("a polygon needs at least 3 points as x,y pairs, got "
                    + xy.length + " numbers");
        }
        Coordinate[] ring = new Coordinate[xy.length / 2 + 1];
        for (int i = 0; i < xy.length / 2; i++) {
            ring[i] = new Coordinate(xy[2 * i], xy[2 * i + 1]);
        }
        ring[ring.length - 1] = ring[0].copy();
        return POLYGONS.createPolygon(ring);
    }

    /**
     * Adds a moving body to the world.
     *
     * @param shape its shape
     * @param pose  where it stands
     * @return its id, used by the other methods
     */
    public int addBody(BodyShape shape, Pose2D pose) {
        return bodies.add(shape, pose);
    }

    /**
     * Makes a body solid or not. A body that is not solid is left out of every query (motion,
     * contact and sensing) until it is made solid again, as a puck held in a gripper is.
     *
     * @param id    the body
     * @param solid whether it is solid; bodies start solid
     */
    public void setSolid(int id, boolean solid) {
        bodies.setSolid(id, solid);
    }

    /**
     * Moves a body, with no collision check.
     *
     * @param id   the body
     * @param pose its new pose
     */
    public void moveBody(int id, Pose2D pose) {
        bodies.move(id, pose);
    }

    /**
     * Gives a body another shape where it stands, with no collision check: a robot's body as its
     * program describes it. The other bodies and the obstacles stay as they are.
     *
     * @param id    the body
     * @param shape its new shape
     */
    public void replaceBody(int id, BodyShape shape) {
        bodies.replace(id, shape);
    }

    /**
     * @param id the body
     * @return its shape
     */
    public BodyShape bodyShape(int id) {
        return bodies.get(id).shape;
    }

    /**
     * @param id the body
     * @return where it stands
     */
    public Pose2D bodyPose(int id) {
        return bodies.get(id).pose;
    }

    /**
     * @param id the body
     * @return its outline in the world
     */
    public Polygon bodyPolygon(int id) {
        return bodies.get(id).polygon;
    }

    /**
     * Whether a shape at a pose would touch an obstacle or another body.
     *
     * @param shape    the shape
     * @param pose     the pose
     * @param ignoreId a body to leave out (the shape's own), or -1
     * @return true if it touches or overlaps something
     */
    public boolean overlaps(BodyShape shape, Pose2D pose, int ignoreId) {
        Coordinate[] ring = shape.ringAt(pose);
        return hits(ring, null, ignoreId);
    }

    /**
     * Follows a body along an arc of constant curvature from its pose and finds where it first
     * touches an obstacle or another body. The body itself is not moved.
     *
     * @param id       the body
     * @param distance arc length in mm, negative backwards
     * @param rotation heading change in radians
     * @return the free part of the motion and the pose reached, short of contact by at most
     *         {@value #CONTACT_TOLERANCE} mm of travel
     */
    public SweepResult sweep(int id, double distance, double rotation) {
        Bodies.Body body = bodies.get(id);
        Pose2D start = body.pose;
        // after each full turn of an arc the body is back where it started: the first turn holds
        // every place it reaches, so the work is bounded by geometry, not by the speed asked
        double part = Math.abs(rotation) > FULL_TURN ? FULL_TURN / Math.abs(rotation) : 1;
        int pieces = pieces(distance * part, rotation * part);
        double travel = Math.abs(distance) + Math.abs(rotation) * body.shape.radius();
        Arc arc = new Arc(body.shape, start, distance, rotation);
        double from = 0;
        Pose2D fromPose = start;
        // each pose's ring is worked out once, for the piece it ends and the one it starts; the
        // start's is the body's own, which ringAt made from the same pose
        Coordinate[] fromRing = body.ring;
        for (int i = 1; i <= pieces; i++) {
            double to = part * i / pieces;
            Arc.Place place = arc.at(to);
            if (hits(fromRing, place.ring(), id)) {
                return contact(arc, id, from, to, travel);
            }
            from = to;
            fromPose = place.pose();
            fromRing = place.ring();
        }
        return new SweepResult(1, part < 1 ? start.advance(distance, rotation) : fromPose, false);
    }

    /**
     * The pieces a sweep cuts a motion into: one for a straight line (the hull of the two ends is
     * exact), else enough that no piece turns more than 3 degrees or runs more than
     * {@value #MAX_PIECE_LENGTH} mm, at most {@value #MAX_PIECES}.
     *
     * @param distance arc length in mm
     * @param rotation heading change in radians, at most a full turn
     * @return the number of pieces, 1 to {@value #MAX_PIECES}
     */
    static int pieces(double distance, double rotation) {
        if (!(Math.abs(rotation) > 1e-12)) {
            return 1;
        }
        double wanted = Math.max(Math.ceil(Math.abs(rotation) / MAX_PIECE_ROTATION),
                Math.ceil(Math.abs(distance) / MAX_PIECE_LENGTH));
        return (int) Math.min(MAX_PIECES, Math.max(1, wanted));
    }

    private SweepResult contact(Arc arc, int id, double free, double blocked, double travel) {
        Arc.Place freePlace = arc.at(free);
        while ((blocked - free) * travel > CONTACT_TOLERANCE) {
            double mid = (free + blocked) / 2;
            Arc.Place midPlace = arc.at(mid);
            if (hits(freePlace.ring(), midPlace.ring(), id)) {
                blocked = mid;
            } else {
                free = mid;
                freePlace = midPlace;
            }
        }
        return new SweepResult(free, freePlace.pose(), true);
    }

    /**
     * Whether the area a simple closed ring encloses, or the convex hull of two, touches an obstacle
     * or another body. The hull is made only when something lies near it: its envelope is the two
     * rings' (the points farthest left, right, down and up are corners of the hull), so what is
     * looked up is what the hull's envelope finds.
     *
     * @param a        a closed ring
     * @param b        another, whose hull with {@code a} is meant, or null for {@code a} alone
     * @param ignoreId a body to leave out, or -1
     */
    private boolean hits(Coordinate[] a, Coordinate[] b, int ignoreId) {
        Envelope env = new Envelope();
        for (Coordinate c : a) {
            env.expandToInclude(c);
        }
        for (int i = 0; b != null && i < b.length; i++) {
            env.expandToInclude(b[i]);
        }
        Coordinate[] ring = null;
        CellGrid.Ids near = motionIds;
        obstacleIndex.query(env, near);
        if (near.size() > 0) {
            ring = b == null ? a : Rings.hull(a, b);
            Polygon g = factory.createPolygon(ring);
            for (int k = 0; k < near.size(); k++) {
                if (obstacleIndex.prepared(near.get(k)).intersects(g)) {
                    return true;
                }
            }
        }
        bodies.near(env, ignoreId, near);
        if (near.size() > 0 && ring == null) {
            ring = b == null ? a : Rings.hull(a, b);
        }
        for (int k = 0; k < near.size(); k++) {
            if (Rings.intersect(ring, bodies.get(near.get(k)).ring)) {
                return true;
            }
        }
        return false;
    }

    /**
     * The distance along a ray to the first edge it meets.
     *
     * @param x        ray origin x, mm
     * @param y        ray origin y, mm
     * @param th       ray direction, radians
     * @param maxRange farthest distance looked at, mm
     * @param ignoreId a body the ray does not see (the sensor's own), or -1
     * @return the distance, or {@code maxRange} if nothing is nearer
     */
    public double rayRange(double x, double y, double th, double maxRange, int ignoreId) {
        double dx = Math.cos(th);
        double dy = Math.sin(th);
        Envelope env = new Envelope(x, x + dx * maxRange, y, y + dy * maxRange);
        double best = edges.rayRange(x, y, dx, dy, maxRange);
        for (Bodies.Body b : bodies.near(env, ignoreId)) {
            for (Segment s : b.segments) {
                best = Math.min(best, s.rayHit(x, y, dx, dy));
            }
        }
        return best;
    }

    /**
     * The distance to the nearest edge inside a cone: a wedge of half-angle {@code halfAngle}
     * about direction {@code th}, out to {@code maxRange}.
     *
     * @param x         apex x, mm
     * @param y         apex y, mm
     * @param th        cone axis, radians
     * @param halfAngle half the cone's opening, radians, below π/2
     * @param maxRange  farthest distance looked at, mm
     * @param ignoreId  a body the cone does not see (the sensor's own), or -1
     * @return the distance, or {@code maxRange} if nothing is nearer
     */
    public double coneRange(double x, double y, double th, double halfAngle, double maxRange, int ignoreId) {
        if (!(halfAngle > 0 && halfAngle < Math.PI / 2)) {
            throw new IllegalArgumentException(halfAngle + " was supplied for halfAngle: it must be between 0 and π/2");
        }
        double rx = Math.cos(th - halfAngle);
        double ry = Math.sin(th - halfAngle);
        double lx = Math.cos(th + halfAngle);
        double ly = Math.sin(th + halfAngle);
        Envelope env = coneEnvelope(x, y, th, halfAngle, maxRange);
        double best = maxRange;
        for (Segment s : edgesNear(env)) {
            best = Math.min(best, s.wedgeDistance(x, y, rx, ry, lx, ly));
        }
        for (Bodies.Body b : bodies.near(env, ignoreId)) {
            for (Segment s : b.segments) {
                best = Math.min(best, s.wedgeDistance(x, y, rx, ry, lx, ly));
            }
        }
        return best;
    }

    /**
     * Where a body touches something: for every obstacle or other body within {@code tolerance}
     * of it, the direction from the body's centre to the nearest point of that obstacle.
     *
     * @param id        the body
     * @param tolerance how near counts as touching, mm
     * @return world directions in radians, one per touching obstacle or body
     */
    public List<Double> contacts(int id, double tolerance) {
        Bodies.Body body = bodies.get(id);
        Envelope env = new Envelope(body.envelope);
        env.expandBy(tolerance);
        List<Double> out = new ArrayList<>();
        CellGrid.Ids near = motionIds;
        obstacleIndex.query(env, near);
        for (int k = 0; k < near.size(); k++) {
            addContact(body, obstacleIndex.polygon(near.get(k)), tolerance, out);
        }
        bodies.near(env, id, near);
        for (int k = 0; k < near.size(); k++) {
            addContact(body, bodies.get(near.get(k)).polygon, tolerance, out);
        }
        return out;
    }

    private static void addContact(Bodies.Body body, Geometry other, double tolerance, List<Double> out) {
        if (body.envelope.distance(other.getEnvelopeInternal()) > tolerance) {
            return;
        }
        // one distance computation gives both whether it is within the tolerance (as
        // isWithinDistance would answer) and the nearest points: a body in contact needs both
        DistanceOp distance = new DistanceOp(body.polygon, other);
        if (distance.distance() <= tolerance) {
            Coordinate p = distance.nearestPoints()[1];
            out.add(Math.atan2(p.y - body.pose.y(), p.x - body.pose.x()));
        }
    }

    /**
     * Whether the straight line between two points crosses no static obstacle (robots are ignored):
     * what heat needs to reach a sensor.
     *
     * @param x1 mm
     * @param y1 mm
     * @param x2 mm
     * @param y2 mm
     * @return true if nothing static is in the way
     */
    public boolean lineOfSight(double x1, double y1, double x2, double y2) {
        double len = Math.hypot(x2 - x1, y2 - y1);
        if (len == 0) {
            return true;
        }
        double dx = (x2 - x1) / len;
        double dy = (y2 - y1) / len;
        for (Segment s : edgesNear(new Envelope(x1, x2, y1, y2))) {
            if (s.rayHit(x1, y1, dx, dy) < len) {
                return false;
            }
        }
        return true;
    }

    /**
     * Gathers the edges of obstacles and bodies within {@code radius} of a point, for many range
     * queries from sensors near it.
     *
     * @param x        centre x, mm
     * @param y        centre y, mm
     * @param radius   mm; must cover every sensor's position plus its maximum range
     * @param ignoreId a body left out (the sensors' own), or -1
     * @return the gathered edges
     */
    public Surroundings around(double x, double y, double radius, int ignoreId) {
        return gather(x, y, radius, ignoreId, new Surroundings());
    }

    /**
     * {@link #around}, into surroundings of the caller's: the same edges in the same order, with
     * the arrays they kept from their last gathering, so that a robot's sensors reading each step
     * allocate nothing for it. The surroundings may be read concurrently with other queries, as
     * {@link #around}'s; one thread gathers into them at a time.
     *
     * @param x        centre x, mm
     * @param y        centre y, mm
     * @param radius   mm; must cover every sensor's position plus its maximum range
     * @param ignoreId a body left out (the sensors' own), or -1
     * @param into     the surroundings to gather into, forgetting what they held
     * @return {@code into}, holding the gathered edges
     */
    public Surroundings gather(double x, double y, double radius, int ignoreId, Surroundings into) {
        Envelope env = new Envelope(x - radius, x + radius, y - radius, y + radius);
        into.begin(x, y);
        edges.gather(env, into);
        bodies.gather(env, ignoreId, into);
        into.finish();
        return into;
    }

    private static Envelope coneEnvelope(double x, double y, double th, double half, double range) {
        Envelope env = new Envelope(x, x, y, y);
        env.expandToInclude(x + range * Math.cos(th - half), y + range * Math.sin(th - half));
        env.expandToInclude(x + range * Math.cos(th + half), y + range * Math.sin(th + half));
        for (int k = -4; k <= 4; k++) {
            double axis = k * Math.PI / 2;
            double d = Math.IEEEremainder(axis - th, 2 * Math.PI);
            if (Math.abs(d) <= half) {
                env.expandToInclude(x + range * Math.cos(axis), y + range * Math.sin(axis));
            }
        }
        return env;
    }
}
