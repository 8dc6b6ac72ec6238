package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Surroundings pass over the edges that lie wholly outside a cone or off a ray without computing
 * their range. The answers stay exactly those of computing every edge's range, also for edges that
 * graze the cone's sides, touch the ray's line or end just behind its origin.
 */
class SurroundingsSkipTest {
    /** Offsets from a cone's side or a ray's line, mm: on it, just off it either way, and clear of it. */
    private static final double[] OFFSETS = {0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6, 1e-4, -1e-4, 1e-3, -1e-3,
            2e-3, -2e-3, 0.5, -0.5, 30, -30};

    /** The cone as Surroundings computed it before they passed over edges: every edge's range up to the cut-off. */
    private static double cone(List<Segment> edges, double cx, double cy, double x, double y, double th, double half,
                               double max) {
        double rx = Math.cos(th - half);
        double ry = Math.sin(th - half);
        double lx = Math.cos(th + half);
        double ly = Math.sin(th + half);
        double best = max;
        double offset = Math.sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy));
        for (Segment e : edges) {
            if (e.distanceTo(cx, cy) - offset > best) {
                break;
            }
            best = Math.min(best, e.wedgeDistance(x, y, rx, ry, lx, ly));
        }
        return best;
    }

    private static double ray(List<Segment> edges, double cx, double cy, double x, double y, double th, double max) {
        double dx = Math.cos(th);
        double dy = Math.sin(th);
        double best = max;
        double offset = Math.sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy));
        for (Segment e : edges) {
            if (e.distanceTo(cx, cy) - offset > best) {
                break;
            }
            best = Math.min(best, e.rayHit(x, y, dx, dy));
        }
        return best;
    }

    /** A point at distance {@code along} on direction {@code a} from (x, y), moved {@code off} to its left. */
    private static double[] at(double x, double y, double a, double along, double off) {
        return new double[] {x + along * Math.cos(a) - off * Math.sin(a), y + along * Math.sin(a) + off * Math.cos(a)};
    }

    @Test
    void grazingEdgesGiveTheRangesOfComputingEveryEdge() {
        Random rnd = new Random(21);
        int finite = 0;
        for (int k = 0; k < 3000; k++) {
            // far from the origin now and then, where coordinates round more coarsely
            double scale = k % 3 == 0 ? 1e6 : 2e4;
            double cx = rnd.nextDouble() * scale;
            double cy = rnd.nextDouble() * scale;
            double x = cx + rnd.nextGaussian() * 200;
            double y = cy + rnd.nextGaussian() * 200;
            double th = rnd.nextDouble() * 2 * Math.PI - Math.PI;
            double half = Math.toRadians(k % 2 == 0 ? 15 : 1 + rnd.nextDouble() * 80);
            List<Segment> edges = new ArrayList<>();
            for (int s = 0; s < 12; s++) {
                // along a side of the cone (or the ray when half is taken as 0), or across its origin
                double side = switch (rnd.nextInt(4)) {
                    case 0 -> th - half;
                    case 1 -> th + half;
                    case 2 -> th;
                    default -> th + Math.PI;
                };
                double off = OFFSETS[rnd.nextInt(OFFSETS.length)] * (rnd.nextBoolean() ? 1 : -1);
                double along1 = rnd.nextDouble() * 6000 - 300;
                double along2 = rnd.nextInt(3) == 0 ? along1 : rnd.nextDouble() * 6000 - 300;
                double off2 = rnd.nextInt(3) == 0 ? off : OFFSETS[rnd.nextInt(OFFSETS.length)];
                double[] p = at(x, y, side, along1, off);
                double[] q = at(x, y, side, along2, off2);
                edges.add(new Segment(p[0], p[1], q[0], q[1]));
            }
            Surroundings near = new Surroundings(cx, cy, edges);
            List<Segment> sorted = near.edges();
            double max = 5000;
            double c = near.cone(x, y, th, half, max);
            assertEquals(cone(sorted, cx, cy, x, y, th, half, max), c, "cone " + k);
            assertEquals(ray(sorted, cx, cy, x, y, th, max), near.ray(x, y, th, max), "ray " + k);
            assertEquals(ray(sorted, cx, cy, x, y, th - half, max), near.ray(x, y, th - half, max), "ray on the side " + k);
            finite += c < max ? 1 : 0;
        }
        assertTrue(finite > 500, "cones that saw something: " + finite);
    }
}
