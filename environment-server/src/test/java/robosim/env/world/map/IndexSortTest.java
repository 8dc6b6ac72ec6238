package robosim.env.world.map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;
import java.util.Comparator;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.map.Coordinates;

/**
 * The radix sort of points gives the order the comparison sort it replaced gave (stable, by one
 * coordinate then the other, -0 equal to 0), and the point store gives back what it was given:
 * so a map gives the same obstacles, line for line, as before.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class IndexSortTest {
    private static final double[] AWKWARD = {0.0, -0.0, 1e-300, -1e-300, 5, -5, 20.5, 1e8, -1e8, 4.9e-324};

    private static int[] byComparison(double[] xy, int major) {
        Comparator<Integer> order = (i, j) -> {
            double a = xy[2 * i + major];
            double b = xy[2 * j + major];
            if (a != b) {
                return a < b ? -1 : 1;
            }
            double c = xy[2 * i + 1 - major];
            double d = xy[2 * j + 1 - major];
            return c < d ? -1 : c > d ? 1 : 0;
        };
        Integer[] idx = new Integer[xy.length / 2];
        Arrays.setAll(idx, i -> i);
        Arrays.sort(idx, order); // stable
        return Arrays.stream(idx).mapToInt(Integer::intValue).toArray();
    }

    private static double[] points(SplittableRandom random, int n) {
        double[] xy = new double[2 * n];
        for (int i = 0; i < xy.length; i++) {
            int kind = random.nextInt(4);
            xy[i] = kind == 0 ? AWKWARD[random.nextInt(AWKWARD.length)]
                    : kind == 1 ? random.nextInt(50) * 20 // a lattice: many equal rows and duplicates
                    : kind == 2 ? random.nextDouble(-1e6, 1e6) : random.nextInt(-100_000, 100_000);
        }
        return xy;
    }

    @Test
    void sortsAsTheStableComparisonSortDid() {
        SplittableRandom random = new SplittableRandom(42);
        for (int n : new int[] {0, 1, 2, 5, 31, 32, 33, 100, 1000, 20_000}) {
            double[] xy = points(random, n);
            for (int major = 0; major < 2; major++) {
                int[] idx = new int[n];
                Arrays.setAll(idx, i -> i);
                IndexSort.sort(idx, xy, major);
                assertArrayEquals(byComparison(xy, major), idx, n + " points by " + major);
                int[] viaStore = new int[n];
                Arrays.setAll(viaStore, i -> i);
                IndexSort.sort(viaStore, Coordinates.of(2, xy, new int[n])::get, major, 1 - major);
                assertArrayEquals(idx, viaStore, n + " points through the store by " + major);
            }
        }
    }
}
