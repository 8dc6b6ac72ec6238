package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Polygon;

/**
 * A ray walks the grid's cells outward and stops past its nearest hit: the range is still the
 * nearest of all edges, for rays that start outside the obstacles' extent, run along the grid's
 * lines or its axes, and cross a field of many small squares (a scanned map's points).
 */
class RayWalkTest {
    private static final double[] CELLS = {GeometryClient.DEFAULT_CELL_SIZE, 500, 97, 20};

    /** 2000 squares of 20 mm on a 20 mm lattice over 10 m x 10 m, as a scanned map's points lie. */
    private static List<Polygon> points(Random rnd) {
        List<Polygon> out = new ArrayList<>();
        for (int i = 0; i < 2000; i++) {
            double x = rnd.nextInt(500) * 20.0;
            double y = rnd.nextInt(500) * 20.0;
            out.add(Worlds.box(x - 10, y - 10, x + 10, y + 10));
        }
        return out;
    }

    private static double brute(List<Polygon> obstacles, double x, double y, double th, double max) {
        double dx = Math.cos(th);
        double dy = Math.sin(th);
        double best = max;
        for (Polygon p : obstacles) {
            Coordinate[] c = p.getExteriorRing().getCoordinates();
            for (int i = 0; i + 1 < c.length; i++) {
                best = Math.min(best, new Segment(c[i].x, c[i].y, c[i + 1].x, c[i + 1].y).rayHit(x, y, dx, dy));
            }
        }
        return best;
    }

    @Test
    void randomRaysFromInsideAndOutsideTheFieldFindTheNearestEdge() {
        Random rnd = new Random(7);
        List<Polygon> field = points(rnd);
        for (double cell : CELLS) {
            GeometryClient g = new GeometryClient(field, cell);
            for (int k = 0; k < 400; k++) {
                double x = -3000 + rnd.nextDouble() * 16000;
                double y = -3000 + rnd.nextDouble() * 16000;
                double th = rnd.nextDouble() * 2 * Math.PI;
                double max = 500 + rnd.nextDouble() * 15000;
                assertEquals(brute(field, x, y, th, max), g.rayRange(x, y, th, max, -1), "cell " + cell);
            }
        }
    }

    @Test
    void raysAlongTheAxesAndTheGridLinesFindTheNearestEdge() {
        Random rnd = new Random(8);
        List<Polygon> field = points(rnd);
        double[] headings = {0, Math.PI / 2, Math.PI, -Math.PI / 2, Math.PI / 4, -3 * Math.PI / 4};
        for (double cell : CELLS) {
            GeometryClient g = new GeometryClient(field, cell);
            for (int k = 0; k < 100; k++) {
                // on a lattice line, which is also an edge of squares and often a cell border
                double x = rnd.nextInt(500) * 20.0 + 10;
                double y = rnd.nextInt(500) * 20.0 - 10;
                for (double th : headings) {
                    assertEquals(brute(field, x, y, th, 8000), g.rayRange(x, y, th, 8000, -1),
                            "cell " + cell + " from (" + x + ", " + y + ") at " + th);
                }
            }
        }
    }
}
