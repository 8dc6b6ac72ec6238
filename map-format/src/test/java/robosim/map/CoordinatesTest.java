package robosim.map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The store of a map's items: what goes in comes back, with its file lines, across blocks. */
class CoordinatesTest {
    @Test
    void theStoreGivesBackItsItemsAndLines() {
        int n = 3 * Coordinates.BLOCK + 17;
        SplittableRandom random = new SplittableRandom(7);
        double[] xy = new double[2 * n];
        for (int i = 0; i < xy.length; i++) {
            xy[i] = random.nextInt(-100_000, 100_000);
        }
        int[] lines = new int[n];
        for (int i = 0, line = 5; i < n; i++) {
            line += i % 1000 == 999 ? 3 : 1; // blank lines now and then
            lines[i] = line;
        }
        Coordinates c = Coordinates.of(2, xy, lines);
        assertEquals(n, c.count());
        assertArrayEquals(xy, c.values());
        assertArrayEquals(lines, c.lineNumbers());
        assertEquals(xy[2 * (n - 1) + 1], c.get(n - 1, 1));
        assertEquals(lines[n - 1], c.line(n - 1));
        int[] odd = {9, 3, 3, 100, 2};
        assertArrayEquals(odd, Coordinates.of(2, new double[10], odd).lineNumbers());
    }
}
