package robosim.env.world.map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.env.world.Obstacle;

/** Points that line up become one rectangle; the others stay squares. */
class PointMergerTest {
    private static List<Obstacle> merge(double... xy) {
        int[] lines = new int[xy.length / 2];
        for (int i = 0; i < lines.length; i++) {
            lines[i] = 10 + i;
        }
        return new PointMerger(xy, lines, 20, 500).merge();
    }

    @Test
    void pointsInARowBecomeOneRectangle() {
        List<Obstacle> out = merge(40, 0, 0, 0, 20, 0, 60, 0);
        assertEquals(1, out.size());
        assertArrayEquals(new double[] {-10, -10, 70, -10, 70, 10, -10, 10}, out.get(0).xy());
        assertEquals(10, out.get(0).line());
    }

    @Test
    void pointsInAColumnBecomeOneRectangle() {
        List<Obstacle> out = merge(0, 40, 0, 0, 0, 20);
        assertEquals(1, out.size());
        assertArrayEquals(new double[] {-10, -10, 10, -10, 10, 50, -10, 50}, out.get(0).xy());
    }

    @Test
    void scatteredPointsStaySquares() {
        List<Obstacle> out = merge(100, 100, 140, 140, 180, 180);
        assertEquals(3, out.size());
        assertArrayEquals(new double[] {130, 130, 150, 130, 150, 150, 130, 150}, out.get(1).xy());
    }

    @Test
    void aGapWiderThanASquareSplitsARow() {
        List<Obstacle> out = merge(0, 0, 20, 0, 100, 0);
        assertEquals(2, out.size());
        assertArrayEquals(new double[] {-10, -10, 30, -10, 30, 10, -10, 10}, out.get(0).xy());
        assertArrayEquals(new double[] {90, -10, 110, -10, 110, 10, 90, 10}, out.get(1).xy());
    }

    @Test
    void aCornerIsARowAndTheRestOfItsColumn() {
        // an L: the row along y = 0 takes the corner, the column above it keeps its own points
        List<Obstacle> out = merge(0, 0, 20, 0, 40, 0, 0, 20, 0, 40);
        assertEquals(2, out.size());
        assertArrayEquals(new double[] {-10, -10, 50, -10, 50, 10, -10, 10}, out.get(0).xy());
        assertArrayEquals(new double[] {-10, 10, 10, 10, 10, 50, -10, 50}, out.get(1).xy());
    }

    @Test
    void aDiagonalOfPointsBecomesOneHexagon() {
        List<Obstacle> out = merge(0, 0, 20, 20, 40, 40, 60, 60);
        assertEquals(1, out.size());
        assertArrayEquals(new double[] {-10, -10, 10, -10, 70, 50, 70, 70, 50, 70, -10, 10}, out.get(0).xy());
    }

    @Test
    void aShallowStaircaseOfRowsBecomesOneObstacle() {
        // three steps of three points, each a row higher and one side past the last
        List<Obstacle> out = merge(0, 0, 20, 0, 40, 0, 60, 20, 80, 20, 100, 20, 120, 40, 140, 40, 160, 40);
        assertEquals(1, out.size());
        assertEquals(10, out.get(0).line());
        assertArrayEquals(new double[] {-10, -10, 50, -10, 170, 30, 170, 50, 110, 50, -10, 10}, out.get(0).xy());
    }

    @Test
    void aSteepStaircaseOfColumnsBecomesOneObstacle() {
        // two columns of three points, the second one side to the right and above the first
        List<Obstacle> out = merge(0, 0, 0, 20, 0, 40, 20, 60, 20, 80, 20, 100);
        assertEquals(1, out.size());
        assertArrayEquals(new double[] {-10, -10, 10, -10, 30, 50, 30, 110, 10, 110, -10, 50}, out.get(0).xy());
    }

    @Test
    void stepsThatBendAwayFromAStraightLineAreNotJoined() {
        // a long run, then single points climbing steeply: the line from the first to the last step
        // passes far from the run's start
        List<Obstacle> out = merge(0, 0, 20, 0, 40, 0, 60, 0, 80, 0, 100, 0, 120, 20, 140, 40, 160, 60, 180, 80);
        assertEquals(2, out.size());
    }
}
