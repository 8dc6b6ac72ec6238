package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.index.strtree.STRtree;

/**
 * Keeping the bodies and edges by grid cells changes no answer: clients with cells of every size
 * answer every query exactly (bit for bit) as one whose single cell holds everything, which looks
 * at every body in id order as a scan of all bodies does; the edges come in the order an STRtree
 * of them gives; rays and cones also agree with a brute-force pass over every edge in the world. Bodies move (across cell borders, out of the
 * grid), some are far larger than a cell, and some change shape.
 */
class GeometryClientGridTest {
    private static final double SPAN = 30000;
    /** One cell for everything: a scan of all bodies in id order, the reference. */
    private static final double ONE_CELL = 1e9;
    private static final double[] CELLS = {ONE_CELL, GeometryClient.DEFAULT_CELL_SIZE, 150, 23};

    private static List<Polygon> obstacles(Random rnd) {
        List<Polygon> obstacles = new ArrayList<>();
        obstacles.add(Worlds.box(0, 0, SPAN, 100));
        obstacles.add(Worlds.box(0, SPAN - 100, SPAN, SPAN));
        for (int i = 0; i < 80; i++) {
            double x = rnd.nextDouble() * SPAN;
            double y = rnd.nextDouble() * SPAN;
            double w = 100 + rnd.nextDouble() * 900;
            double h = 100 + rnd.nextDouble() * 900;
            obstacles.add(Worlds.box(x, y, x + w, y + h));
        }
        return obstacles;
    }

    private static BodyShape shape(Random rnd, int i) {
        if (i % 25 == 0) {
            return BodyShape.disc(1500 + rnd.nextDouble() * 2000, 24);
        }
        if (i % 3 == 0) {
            return BodyShape.disc(150 + rnd.nextDouble() * 200, 8 + 4 * rnd.nextInt(4));
        }
        return Worlds.P3DX;
    }

    private static Pose2D pose(Random rnd) {
        return new Pose2D(rnd.nextDouble() * SPAN, rnd.nextDouble() * SPAN, rnd.nextDouble() * 2 * Math.PI);
    }

    private final List<GeometryClient> clients = new ArrayList<>();
    private List<Polygon> obstacles;

    private void build(Random rnd, int bodies) {
        obstacles = obstacles(rnd);
        for (double cell : CELLS) {
            clients.add(new GeometryClient(obstacles, cell));
        }
        for (int i = 0; i < bodies; i++) {
            BodyShape s = shape(rnd, i);
            Pose2D p = pose(rnd);
            for (GeometryClient g : clients) {
                assertEquals(i, g.addBody(s, p));
            }
        }
    }

    private void moveSome(Random rnd, int bodies) {
        for (int i = 0; i < bodies; i++) {
            if (rnd.nextInt(3) != 0) {
                continue;
            }
            Pose2D at = clients.get(0).bodyPose(i);
            Pose2D to = rnd.nextInt(30) == 0
                    // now and then far away, even outside the world
                    ? new Pose2D(rnd.nextDouble() * SPAN * 1.4 - SPAN * 0.2, rnd.nextDouble() * SPAN * 1.4 - SPAN * 0.2, 1)
                    : at.advance(rnd.nextGaussian() * 200, rnd.nextGaussian() * 0.3);
            BodyShape other = rnd.nextInt(50) == 0 ? shape(rnd, rnd.nextInt(100)) : null;
            for (GeometryClient g : clients) {
                g.moveBody(i, to);
                if (other != null) {
                    g.replaceBody(i, other);
                }
            }
        }
    }

    private static double bruteRay(List<Polygon> obstacles, GeometryClient g, int bodies, double x, double y,
                                   double th, double max, int ignore) {
        double dx = Math.cos(th);
        double dy = Math.sin(th);
        double best = max;
        for (Segment s : edges(obstacles, g, bodies, ignore)) {
            best = Math.min(best, s.rayHit(x, y, dx, dy));
        }
        return best;
    }

    private static List<Segment> edges(List<Polygon> obstacles, GeometryClient g, int bodies, int ignore) {
        List<Segment> all = new ArrayList<>();
        List<Coordinate[]> rings = new ArrayList<>();
        for (Polygon p : obstacles) {
            rings.add(p.getExteriorRing().getCoordinates());
        }
        for (int i = 0; i < bodies; i++) {
            if (i != ignore) {
                rings.add(g.bodyPolygon(i).getExteriorRing().getCoordinates());
            }
        }
        for (Coordinate[] c : rings) {
            for (int k = 0; k + 1 < c.length; k++) {
                all.add(new Segment(c[k].x, c[k].y, c[k + 1].x, c[k + 1].y));
            }
        }
        return all;
    }

    @Test
    void rangesAndSurroundingsAreThoseOfAScanOfAllBodies() {
        Random rnd = new Random(2026);
        int bodies = 250;
        build(rnd, bodies);
        GeometryClient reference = clients.get(0);
        for (int round = 0; round < 6; round++) {
            for (int k = 0; k < 150; k++) {
                double x = rnd.nextDouble() * SPAN;
                double y = rnd.nextDouble() * SPAN;
                double th = rnd.nextDouble() * 2 * Math.PI;
                double max = 500 + rnd.nextDouble() * 8000;
                int ignore = rnd.nextInt(bodies + 1) - 1;
                double ray = reference.rayRange(x, y, th, max, ignore);
                double cone = reference.coneRange(x, y, th, Math.toRadians(15), max, ignore);
                assertEquals(bruteRay(obstacles, reference, bodies, x, y, th, max, ignore), ray, 1e-6, "brute-force ray");
                Surroundings near = reference.around(x, y, max + 300, ignore);
                for (GeometryClient g : clients) {
                    assertEquals(ray, g.rayRange(x, y, th, max, ignore), "ray");
                    assertEquals(cone, g.coneRange(x, y, th, Math.toRadians(15), max, ignore), "cone");
                    Surroundings mine = g.around(x, y, max + 300, ignore);
                    assertEquals(near.edges(), mine.edges(), "the same edges in the same order");
                    for (int s = 0; s < 8; s++) {
                        double ax = x + rnd.nextGaussian() * 100;
                        double ay = y + rnd.nextGaussian() * 100;
                        double a = rnd.nextDouble() * 2 * Math.PI;
                        assertEquals(near.cone(ax, ay, a, Math.toRadians(15), max), mine.cone(ax, ay, a, Math.toRadians(15), max));
                        assertEquals(near.ray(ax, ay, a, max), mine.ray(ax, ay, a, max));
                    }
                }
            }
            moveSome(rnd, bodies);
        }
    }

    @Test
    void collisionsContactsAndSweepsAreThoseOfAScanOfAllBodies() {
        Random rnd = new Random(99);
        int bodies = 200;
        build(rnd, bodies);
        GeometryClient reference = clients.get(0);
        for (int round = 0; round < 4; round++) {
            for (int id = 0; id < bodies; id++) {
                double tolerance = rnd.nextDouble() * 400;
                List<Double> contacts = reference.contacts(id, tolerance);
                boolean overlaps = reference.overlaps(Worlds.P3DX, reference.bodyPose(id), id);
                Pose2D somewhere = pose(rnd);
                boolean there = reference.overlaps(Worlds.P3DX, somewhere, -1);
                double distance = rnd.nextGaussian() * 600;
                double rotation = rnd.nextGaussian() * 0.5;
                SweepResult sweep = id % 4 == 0 ? reference.sweep(id, distance, rotation) : null;
                for (GeometryClient g : clients) {
                    assertEquals(contacts, g.contacts(id, tolerance), "contacts of " + id);
                    assertEquals(overlaps, g.overlaps(Worlds.P3DX, g.bodyPose(id), id));
                    assertEquals(there, g.overlaps(Worlds.P3DX, somewhere, -1));
                    if (sweep != null) {
                        assertEquals(sweep, g.sweep(id, distance, rotation), "sweep of " + id);
                    }
                }
            }
            moveSome(rnd, bodies);
        }
    }

    @Test
    void edgesComeAsAnStrTreeOfThemGivesThem() {
        Random rnd = new Random(8);
        List<Polygon> obs = new ArrayList<>(obstacles(rnd));
        obs.add(Worlds.room());
        STRtree tree = new STRtree();
        for (Polygon p : obs) {
            List<Coordinate[]> rings = new ArrayList<>();
            rings.add(p.getExteriorRing().getCoordinates());
            for (int i = 0; i < p.getNumInteriorRing(); i++) {
                rings.add(p.getInteriorRingN(i).getCoordinates());
            }
            for (Coordinate[] c : rings) {
                for (int k = 0; k + 1 < c.length; k++) {
                    Segment e = new Segment(c[k].x, c[k].y, c[k + 1].x, c[k + 1].y);
                    tree.insert(new Envelope(e.x1(), e.x2(), e.y1(), e.y2()), e);
                }
            }
        }
        for (double cell : CELLS) {
            GeometryClient g = new GeometryClient(obs, cell);
            for (int k = 0; k < 2000; k++) {
                double x = rnd.nextDouble() * SPAN * 1.2 - SPAN * 0.1 - 2100;
                double y = rnd.nextDouble() * SPAN * 1.2 - SPAN * 0.1 - 2100;
                double side = k % 10 == 0 ? rnd.nextDouble() * SPAN : rnd.nextDouble() * 3000;
                Envelope env = new Envelope(x, x + side * rnd.nextDouble(), y, y + side * rnd.nextDouble());
                // the same edges, in the same order (equal edges of two obstacles told apart by identity)
                List<?> expected = tree.query(env);
                List<Segment> actual = g.edgesNear(env);
                assertEquals(expected.size(), actual.size(), "cell " + cell + ", " + env);
                for (int i = 0; i < actual.size(); i++) {
                    assertEquals(expected.get(i), actual.get(i), "edge " + i + ", cell " + cell + ", " + env);
                }
            }
        }
    }

    @Test
    void aReplacedBodyIsAsIfItHadBeenAddedSo() {
        Random rnd = new Random(5);
        List<Polygon> obs = obstacles(rnd);
        GeometryClient replaced = new GeometryClient(obs);
        GeometryClient direct = new GeometryClient(obs);
        BodyShape big = BodyShape.rectangle(400, 400, 600);
        for (int i = 0; i < 50; i++) {
            Pose2D p = pose(rnd);
            replaced.addBody(Worlds.P3DX, p);
            direct.addBody(i == 17 ? big : Worlds.P3DX, p);
        }
        replaced.replaceBody(17, big);
        assertEquals(big, replaced.bodyShape(17));
        assertArrayEquals(direct.bodyPolygon(17).getCoordinates(), replaced.bodyPolygon(17).getCoordinates());
        Pose2D p = replaced.bodyPose(17);
        for (int k = 0; k < 500; k++) {
            double th = rnd.nextDouble() * 2 * Math.PI;
            double x = p.x() + rnd.nextGaussian() * 2000;
            double y = p.y() + rnd.nextGaussian() * 2000;
            assertEquals(direct.rayRange(x, y, th, 5000, -1), replaced.rayRange(x, y, th, 5000, -1));
            assertEquals(direct.around(x, y, 5300, 3).edges(), replaced.around(x, y, 5300, 3).edges());
        }
        assertEquals(direct.contacts(17, 3000), replaced.contacts(17, 3000));
    }

    @Test
    void stableOrderIsTheOrderOfAStableSort() {
        Random rnd = new Random(3);
        // one order sorting every key array in turn, longer and shorter, as a gathering's does
        DistanceOrder reused = new DistanceOrder();
        for (int kind = 0; kind < 6; kind++) {
            for (int n : new int[] {0, 1, 2, 15, 16, 17, 33, 100, 257, 1000}) {
                double[] keys = new double[n];
                for (int i = 0; i < n; i++) {
                    keys[i] = switch (kind) {
                        // many ties, and zeros of both signs
                        case 0 -> rnd.nextInt(4) == 0 ? (rnd.nextBoolean() ? 0.0 : -0.0) : rnd.nextInt(n / 3 + 1) * 0.5;
                        // distances spread as an edge's are
                        case 1 -> Math.sqrt(rnd.nextDouble()) * 7000;
                        // bunched up near one value, one far away
                        case 2 -> i == n / 2 ? 1e9 : 1000 + rnd.nextDouble();
                        // all equal
                        case 3 -> 42;
                        // keys only one ulp apart
                        case 4 -> Math.nextUp(1000.0 + rnd.nextInt(3) * Math.ulp(1000.0));
                        // now and then not a number or infinite
                        default -> rnd.nextInt(20) == 0 ? (rnd.nextBoolean() ? Double.NaN : Double.POSITIVE_INFINITY)
                                : rnd.nextDouble() * 5000;
                    };
                }
                Integer[] boxed = new Integer[n];
                for (int i = 0; i < n; i++) {
                    boxed[i] = i;
                }
                Arrays.sort(boxed, (a, b) -> Double.compare(keys[a], keys[b]));
                int[] expected = Arrays.stream(boxed).mapToInt(Integer::intValue).toArray();
                assertArrayEquals(expected, DistanceOrder.of(keys), "kind " + kind + ", n = " + n);
                assertArrayEquals(expected, DistanceOrder.mergeOrder(keys), "kind " + kind + ", n = " + n);
                assertArrayEquals(expected, Arrays.copyOf(reused.sort(keys, n), n), "kind " + kind + ", n = " + n + ", reused");
            }
        }
    }
}
