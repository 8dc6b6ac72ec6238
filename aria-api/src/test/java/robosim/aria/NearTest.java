package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** {@link Near}'s answers are {@code Math.hypot}'s, at the bound and far from it. */
class NearTest {
    @Test
    void answersAsHypotDoes() {
        SplittableRandom random = new SplittableRandom(7);
        double[] bounds = {0, -1, 1e-300, 0.5, 50, 75, 600, 3000, 1e300, Double.MAX_VALUE, Double.NaN,
                Double.POSITIVE_INFINITY};
        for (int i = 0; i < 200_000; i++) {
            double dist = i % 3 == 0 ? bounds[random.nextInt(bounds.length)] : random.nextDouble(0, 5000);
            double dx;
            double dy;
            if (i % 2 == 0 && Double.isFinite(dist)) {
                // on the bound's circle, or a hair off it: where a rounding would show
                double a = random.nextDouble(0, 2 * Math.PI);
                double r = dist * (1 + (random.nextInt(5) - 2) * Math.ulp(1.0));
                dx = r * Math.cos(a);
                dy = r * Math.sin(a);
            } else {
                dx = random.nextDouble(-1e4, 1e4) * (i % 7 == 0 ? 1e150 : 1);
                dy = random.nextDouble(-1e4, 1e4);
            }
            assertEquals(Math.hypot(dx, dy) < dist, Near.within(dx, dy, dist), dx + ", " + dy + " < " + dist);
            assertEquals(Math.hypot(dx, dy) > dist, Near.beyond(dx, dy, dist), dx + ", " + dy + " > " + dist);
        }
    }

    @Test
    void nanAndInfinityAnswerAsHypotDoes() {
        double[] odd = {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, 0, -0.0, 1e200};
        for (double dx : odd) {
            for (double dy : odd) {
                for (double dist : new double[] {50, Double.NaN, Double.POSITIVE_INFINITY, 0}) {
                    assertEquals(Math.hypot(dx, dy) < dist, Near.within(dx, dy, dist), dx + ", " + dy + " < " + dist);
                    assertEquals(Math.hypot(dx, dy) > dist, Near.beyond(dx, dy, dist), dx + ", " + dy + " > " + dist);
                }
            }
        }
    }
}
