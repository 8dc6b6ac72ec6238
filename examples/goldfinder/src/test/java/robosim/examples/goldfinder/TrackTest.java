package robosim.examples.goldfinder;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The line a Gold robot drives through its committed cells of a 1500 mm maze: straight through a
 * cell it crosses, a quarter circle of 750 mm about the inner corner of a cell where it turns, and
 * the last cell's centre as its end.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class TrackTest {
    private static final double CELL = 1500;
    private static final int SOUTH = 3;

    @Test
    void aStandingRobotDrivesStraightThroughCellsItCrossesToTheLastOnesCentre() {
        Course c = new Course(0, 0);
        c.commit(MazeKnowledge.key(1, 0));
        c.commit(MazeKnowledge.key(2, 0));
        Track t = new Track(c, CELL, 750, 750);
        assertEquals(750 + 1500 + 750, t.toStop(), 1e-9);
        assertEquals(Double.POSITIVE_INFINITY, t.toBend());
        assertFalse(t.bendsFirst());
        assertEquals(0, t.headingHere(), 1e-9);
        assertEquals(1500 + 750, t.pointAhead(1500)[0], 1e-9);
        assertEquals(3750, t.pointAhead(9000)[0], 1e-9, "nothing lies past the end");
    }

    @Test
    void whereTheWayTurnsTheTrackIsAQuarterCircleAboutTheCellsInnerCorner() {
        // driving east into (1, 0), which it leaves north for (1, 1): the bend is about (1500, 1500)
        Course c = new Course(0, 0);
        c.commit(MazeKnowledge.key(1, 0));
        c.moveTo(1, 0);
        c.commit(MazeKnowledge.key(1, 1));
        Track t = new Track(c, CELL, 1500, 750);
        assertTrue(t.bendsFirst());
        assertEquals(0, t.toBend(), 1e-9);
        assertEquals(Math.PI / 2 * 750 + 750, t.toStop(), 1e-9);
        for (double s = 0; s <= Math.PI / 2 * 750; s += 100) {
            double[] p = t.pointAhead(s);
            assertEquals(750, Math.hypot(p[0] - 1500, p[1] - 1500), 1e-9, "on the circle at " + s);
        }
        assertEquals(0, t.headingHere(), 0.5, "it comes in heading east");
        double[] out = t.pointAhead(Math.PI / 2 * 750);
        assertEquals(2250, out[0], 1e-9, "it leaves through the middle of the north side");
        assertEquals(1500, out[1], 1e-9);
    }

    @Test
    void theWayToTheNextBendAndToACellCountFromWhereTheRobotIs() {
        // standing west of (0, 0)'s centre, committed east to (1, 0) and (2, 0), then north to (2, 1)
        Course c = new Course(0, 0);
        c.commit(MazeKnowledge.key(1, 0));
        c.commit(MazeKnowledge.key(2, 0));
        c.commit(MazeKnowledge.key(2, 1));
        Track t = new Track(c, CELL, 500, 750);
        assertEquals(1000 + 1500, t.toBend(), 1e-9);
        assertEquals(1000, t.toCell(1), 1e-9);
        assertEquals(-0.0, t.toCell(0), 1e-9);
        assertEquals(SOUTH, c.lastEntry(), "it comes into (2, 1) from the south");
    }

    @Test
    void cellsThatAreNotNeighboursHaveNoSideBetweenThem() {
        assertEquals(1, Track.sideTowards(MazeKnowledge.key(3, 3), MazeKnowledge.key(3, 4)));
        assertThrows(IllegalArgumentException.class,
                () -> Track.sideTowards(MazeKnowledge.key(3, 3), MazeKnowledge.key(4, 4)));
    }
}
