package robosim.examples.goldfinder;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** Where a Gold robot is and goes: its cell moves on by the cells of its run, and its wait is counted. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class CourseTest {
    private static final int EAST = 0;
    private static final int NORTH = 1;
    private static final int WEST = 2;
    private static final int SOUTH = 3;

    @Test
    void theSidesLeadEastNorthWestAndSouth() {
        assertEquals(1, Directions.dx(EAST));
        assertEquals(0, Directions.dy(EAST));
        assertEquals(1, Directions.dy(NORTH));
        assertEquals(-1, Directions.dx(WEST));
        assertEquals(-1, Directions.dy(SOUTH));
    }

    @Test
    void aRunCountsItsCellsFromTheRobotsCellAndMovesItOnWhenDriven() {
        Course c = new Course(2, 3);
        c.run(NORTH, 3);
        assertEquals(2, c.aheadX(3));
        assertEquals(6, c.aheadY(3));
        c.advance(2);
        assertEquals(MazeKnowledge.key(2, 5), c.here());
        c.run(WEST, 1);
        c.advance(c.cells());
        assertEquals(1, c.x());
        assertEquals(5, c.y());
    }

    @Test
    void aRunIsCutShortToTheCellsSeenClearNeverLengthened() {
        Course c = new Course(0, 0);
        c.run(EAST, 4);
        c.shortenTo(6);
        assertEquals(4, c.cells());
        c.shortenTo(2);
        assertEquals(2, c.cells());
        c.shortenTo(0);
        assertEquals(0, c.cells());
    }

    @Test
    void waitingForACellCountsStepsUntilItStops() {
        Course c = new Course(0, 0);
        assertEquals(-1, c.want());
        c.startWaiting(MazeKnowledge.key(1, 0));
        c.waitOneStep();
        c.waitOneStep();
        assertEquals(MazeKnowledge.key(1, 0), c.want());
        assertEquals(2, c.waited());
        c.restartPatience();
        assertEquals(0, c.waited());
        assertEquals(MazeKnowledge.key(1, 0), c.want());
        c.stopWaiting();
        assertEquals(-1, c.want());
        assertEquals(0, c.waited());
    }
}
