package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.index.strtree.STRtree;

/**
 * {@link StrOrder} gives exactly the order of a JTS STRtree's leaves, and {@link ObstacleIndex}
 * answers exactly as an STRtree of the polygons did: for every size around the tree's level and
 * slice boundaries, with ties (boxes sharing centres, repeated boxes, points), both signs of zero,
 * boxes given either way round, and coordinates that are not finite.
 */
class StrOrderTest {
    private static final Envelope EVERYTHING = new Envelope(Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);

    /** The order an STRtree itself gives the items of these boxes. */
    private static int[] treeOrder(double[] boxes) {
        STRtree tree = new STRtree();
        for (int i = 0; i < boxes.length / 4; i++) {
            tree.insert(new Envelope(boxes[4 * i], boxes[4 * i + 2], boxes[4 * i + 1], boxes[4 * i + 3]), i);
        }
        return tree.query(EVERYTHING).stream().mapToInt(o -> (Integer) o).toArray();
    }

    /** Boxes on a coarse lattice, so that many share a centre, some repeated, some points, some given backwards. */
    private static double[] boxes(Random rnd, int n, int lattice) {
        double[] out = new double[4 * n];
        for (int i = 0; i < n; i++) {
            double x = rnd.nextInt(lattice) * 10 - lattice * 5;
            double y = rnd.nextInt(lattice) * 10 - lattice * 5;
            double w = rnd.nextInt(4) * 10;
            double h = rnd.nextInt(4) * 10;
            if (i > 0 && rnd.nextInt(10) == 0) {
                System.arraycopy(out, 4 * rnd.nextInt(i), out, 4 * i, 4);
                continue;
            }
            boolean backwards = rnd.nextBoolean();
            out[4 * i] = zero(backwards ? x + w : x, rnd);
            out[4 * i + 1] = zero(backwards ? y + h : y, rnd);
            out[4 * i + 2] = zero(backwards ? x : x + w, rnd);
            out[4 * i + 3] = zero(backwards ? y : y + h, rnd);
        }
        return out;
    }

    private static double zero(double v, Random rnd) {
        return v == 0 && rnd.nextBoolean() ? -0.0 : v;
    }

    @ParameterizedTest(name = "{0} items")
    @ValueSource(ints = {0, 1, 2, 9, 10, 11, 99, 100, 101, 999, 1000, 1001, 4321, 10000, 10001, 65537, 250000})
    void theOrderIsTheTreesOwn(int n) {
        Random rnd = new Random(n);
        for (int lattice : new int[] {3, 40, 100000}) {
            double[] boxes = boxes(rnd, n, lattice);
            assertArrayEquals(treeOrder(boxes), StrOrder.leafOrder(boxes), "lattice " + lattice);
        }
    }

    @Test
    void coordinatesThatAreNotFiniteAreOrderedByTheTree() {
        double[] boxes = boxes(new Random(5), 500, 50);
        boxes[17] = Double.POSITIVE_INFINITY;
        boxes[40] = Double.NEGATIVE_INFINITY;
        boxes[41] = Double.POSITIVE_INFINITY;
        assertArrayEquals(treeOrder(boxes), StrOrder.leafOrder(boxes));
    }

    @ParameterizedTest(name = "{0} obstacles")
    @ValueSource(ints = {1, 7, 300, 5000})
    void obstaclesAreAnsweredAsAnStrtreeOfThemAnswered(int n) {
        Random rnd = new Random(n);
        List<Polygon> obstacles = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            double x = rnd.nextInt(200) * 50.0;
            double y = rnd.nextInt(200) * 50.0;
            double s = 10 + rnd.nextInt(3) * 200;
            obstacles.add(GeometryClient.polygon(x, y, x + s, y, x + s / 2, y + s));
            if (rnd.nextInt(20) == 0) {
                obstacles.add(obstacles.get(rnd.nextInt(obstacles.size())));
            }
        }
        STRtree tree = new STRtree();
        for (Polygon p : obstacles) {
            tree.insert(p.getEnvelopeInternal(), p);
        }
        for (double cell : new double[] {GeometryClient.DEFAULT_CELL_SIZE, 37}) {
            ObstacleIndex index = new ObstacleIndex(obstacles, ObstacleEdges.extent(obstacles), cell);
            for (int q = 0; q < 300; q++) {
                double x = rnd.nextDouble() * 12000 - 1000;
                double y = rnd.nextDouble() * 12000 - 1000;
                Envelope env = new Envelope(x, x + rnd.nextDouble() * 3000, y, y + rnd.nextDouble() * 3000);
                List<?> expected = tree.query(env);
                int[] found = index.query(env);
                assertEquals(expected.size(), found.length, "query " + env);
                for (int i = 0; i < found.length; i++) {
                    assertSame(expected.get(i), index.polygon(found[i]), "query " + env);
                }
            }
        }
    }
}
