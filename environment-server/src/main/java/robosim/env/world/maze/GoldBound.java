package robosim.env.world.maze;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.LineString;
import org.locationtech.jts.geom.Point;
import org.locationtech.jts.geom.prep.PreparedGeometry;
import org.locationtech.jts.geom.prep.PreparedGeometryFactory;
import org.locationtech.jts.operation.union.UnaryUnionOp;
import robosim.env.core.Simulation;
import robosim.env.world.Obstacle;
import robosim.env.world.RobotSpec;
import robosim.env.world.World;
import robosim.geometry.GeometryClient;
import robosim.protocol.RobotParameters;

/**
 * A true lower bound on the steps a team takes to find a world's gold: no robot program, however
 * well it knew the world, finds it sooner.
 *
 * <p>The nearest robot drives the shortest path its centre can take around the walls (each wall
 * grown by the radius of the largest disc inside the robot's body) to where the gold is
 * {@value Simulation#GOLD_FOUND_DISTANCE} mm away, at the robot's top speed, reached from rest at
 * its acceleration, with no time to turn. Every simplification makes the bound lower, never higher:
 * <ul>
 * <li>the walls are grown by polygons whose corners lie on the circle, so they lie within the
 *     truly grown walls and the path around them is no longer than the true one;</li>
 * <li>the sight lines between corners are tested against walls grown by {@value #SLACK} mm less;</li>
 * <li>movable objects are left out, as if pushed aside for free;</li>
 * <li>one step is taken off for the step's discretisation.</li>
 * </ul>
 */
public final class GoldBound {
    /** Sides per quarter circle of a grown wall's rounded corner. */
    private static final int QUADRANT_SEGMENTS = 3;
    /** How much less the walls are grown for the sight test than for the corners, mm. */
    static final double SLACK = 0.5;
    /** A corner is one the path can bend round when the walls lie this near it on its inner side, mm. */
    private static final double PROBE = 0.25;
    private static final GeometryFactory FACTORY = new GeometryFactory();

    private GoldBound() {
    }

    /**
     * The bound for a world's team.
     *
     * @param world a world with gold and robots
     * @return steps: the fewest in which the team's nearest robot can come within
     *         {@value Simulation#GOLD_FOUND_DISTANCE} mm of the gold
     * @throws IllegalArgumentException if the world has no gold or no robots
     */
    public static long steps(World world) {
        if (world.gold() == null || world.robots().isEmpty()) {
            throw new IllegalArgumentException("world " + world.name() + " has no gold or no robots: its lower bound"
                    + " needs both");
        }
        List<Geometry> rings = new ArrayList<>();
        for (Obstacle o : world.obstacles()) {
            rings.add(GeometryClient.polygon(o.xy()));
        }
        Geometry walls = rings.isEmpty() ? FACTORY.createPolygon() : UnaryUnionOp.union(rings);
        Map<Double, Paths> byRadius = new HashMap<>();
        double best = Double.POSITIVE_INFINITY;
        for (RobotSpec r : world.robots()) {
            RobotParameters p = r.parameters();
            Paths paths = byRadius.computeIfAbsent(innerRadius(p), radius -> new Paths(walls, radius, world));
            double distance = Math.max(0, paths.toGold(r.x(), r.y()) - Simulation.GOLD_FOUND_DISTANCE);
            best = Math.min(best, seconds(distance, p.maxVelocity(), p.transAccel()));
        }
        if (best == Double.POSITIVE_INFINITY) {
            return Long.MAX_VALUE;
        }
        return Math.max(0, (long) Math.ceil(best * 1000 / world.stepMs() - 1e-9) - 1);
    }

    /** The radius of the largest disc about the centre of rotation that the body holds, mm. */
    static double innerRadius(RobotParameters p) {
        if (p.isRound()) {
            return p.robotRadius();
        }
        return Math.min(Math.min(p.robotLengthFront(), p.robotLengthRear()), p.robotWidth() / 2);
    }

    /** Seconds to cover a distance from rest at {@code accel}, capped at {@code top}, not stopping at the end. */
    static double seconds(double distance, double top, double accel) {
        double rampDistance = top * top / (2 * accel);
        return distance >= rampDistance ? (distance - rampDistance) / top + top / accel : Math.sqrt(2 * distance / accel);
    }

    /** Shortest paths to the gold around walls grown by one radius: a visibility graph of the grown walls' corners. */
    private static final class Paths {
        private final PreparedGeometry blocking;
        private final Coordinate[] corners;
        private final double[] toGold;
        private final Coordinate gold;

        Paths(Geometry walls, double radius, World world) {
            Geometry grown = walls.isEmpty() ? walls : walls.buffer(radius, QUADRANT_SEGMENTS);
            Geometry sight = walls.isEmpty() ? walls : walls.buffer(Math.max(0, radius - SLACK), QUADRANT_SEGMENTS);
            blocking = PreparedGeometryFactory.prepare(sight);
            gold = new Coordinate(world.gold().x(), world.gold().y());
            corners = corners(grown);
            toGold = new double[corners.length];
            Arrays.fill(toGold, Double.POSITIVE_INFINITY);
            boolean[] done = new boolean[corners.length];
            for (int i = 0; i < corners.length; i++) {
                if (sees(corners[i], gold)) {
                    toGold[i] = corners[i].distance(gold);
                }
            }
            // Dijkstra on the dense graph: n picks, each relaxing every corner it sees
            for (int round = 0; round < corners.length; round++) {
                int u = -1;
                for (int i = 0; i < corners.length; i++) {
                    if (!done[i] && (u < 0 || toGold[i] < toGold[u])) {
                        u = i;
                    }
                }
                if (u < 0 || toGold[u] == Double.POSITIVE_INFINITY) {
                    break;
                }
                done[u] = true;
                for (int v = 0; v < corners.length; v++) {
                    double through = toGold[u] + corners[u].distance(corners[v]);
                    if (!done[v] && through < toGold[v] && sees(corners[u], corners[v])) {
                        toGold[v] = through;
                    }
                }
            }
        }

        /** The shortest path's length from a point to the gold, mm; infinite when walls cut it off. */
        double toGold(double x, double y) {
            Coordinate from = new Coordinate(x, y);
            if (sees(from, gold)) {
                return from.distance(gold);
            }
            double best = Double.POSITIVE_INFINITY;
            for (int i = 0; i < corners.length; i++) {
                double through = from.distance(corners[i]) + toGold[i];
                if (through < best && sees(from, corners[i])) {
                    best = through;
                }
            }
            return best;
        }

        private boolean sees(Coordinate a, Coordinate b) {
            LineString line = FACTORY.createLineString(new Coordinate[] {a, b});
            return !blocking.intersects(line);
        }

        /** The grown walls' corners that jut into the open: the only places a shortest path bends. */
        private static Coordinate[] corners(Geometry grown) {
            List<Coordinate> out = new ArrayList<>();
            PreparedGeometry solid = PreparedGeometryFactory.prepare(grown);
            for (int g = 0; g < grown.getNumGeometries(); g++) {
                org.locationtech.jts.geom.Polygon polygon = (org.locationtech.jts.geom.Polygon) grown.getGeometryN(g);
                addCorners(polygon.getExteriorRing().getCoordinates(), solid, out);
                for (int h = 0; h < polygon.getNumInteriorRing(); h++) {
                    addCorners(polygon.getInteriorRingN(h).getCoordinates(), solid, out);
                }
            }
            return out.toArray(Coordinate[]::new);
        }

        private static void addCorners(Coordinate[] ring, PreparedGeometry solid, List<Coordinate> out) {
            int n = ring.length - 1; // closed: the last repeats the first
            for (int i = 0; i < n; i++) {
                Coordinate v = ring[i];
                Coordinate a = ring[(i + n - 1) % n];
                Coordinate b = ring[(i + 1) % n];
                double ax = a.x - v.x;
                double ay = a.y - v.y;
                double bx = b.x - v.x;
                double by = b.y - v.y;
                double la = Math.hypot(ax, ay);
                double lb = Math.hypot(bx, by);
                double sx = ax / la + bx / lb;
                double sy = ay / la + by / lb;
                double ls = Math.hypot(sx, sy);
                if (ls < 1e-9) {
                    continue; // straight on: no corner
                }
                // the corner juts into the open when the wall lies inside its angle
                Point inside = FACTORY.createPoint(new Coordinate(v.x + PROBE * sx / ls, v.y + PROBE * sy / ls));
                if (solid.contains(inside)) {
                    out.add(new Coordinate(v));
                }
            }
        }
    }
}
