package robosim.examples.goldfinder;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** Where a Gold robot is and goes: its cell moves on through the cells it committed to, and its wait is counted. */
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
    void comingIntoTheNextCommittedCellMovesTheCourseOnAndNotesTheSideItCameInBy() {
        Course c = new Course(2, 3);
        assertEquals(-1, c.entry(), "it starts standing");
        c.commit(MazeKnowledge.key(2, 4));
        c.commit(MazeKnowledge.key(1, 4));
        assertEquals(MazeKnowledge.key(1, 4), c.last());
        assertEquals(EAST, c.lastEntry(), "it comes into (1, 4) from the east");
        assertTrue(c.moveTo(2, 4));
        assertEquals(SOUTH, c.entry());
        assertEquals(List.of(MazeKnowledge.key(1, 4)), c.ahead());
        assertFalse(c.moveTo(2, 4), "the same cell again changes nothing");
    }

    @Test
    void comingIntoACellNotCommittedToDropsTheCommittedOnesAndStands() {
        Course c = new Course(0, 0);
        c.commit(MazeKnowledge.key(1, 0));
        c.moveTo(0, 1);
        assertEquals(List.of(), c.ahead());
        assertEquals(-1, c.entry());
    }

    @Test
    void committedCellsCanBeGivenUpFromAnyOfThemOnAndAStandingRobotHoldsNone() {
        Course c = new Course(0, 0);
        c.commit(MazeKnowledge.key(1, 0));
        c.commit(MazeKnowledge.key(2, 0));
        c.commit(MazeKnowledge.key(3, 0));
        c.cutFrom(1);
        assertEquals(List.of(MazeKnowledge.key(1, 0)), c.ahead());
        c.moveTo(1, 0);
        c.stand();
        assertEquals(List.of(), c.ahead());
        assertEquals(-1, c.entry());
    }

    @Test
    void onlyANeighbourOfTheLastCommittedCellCanBeCommitted() {
        Course c = new Course(0, 0);
        assertThrows(IllegalArgumentException.class, () -> c.commit(MazeKnowledge.key(2, 0)));
        assertThrows(IllegalArgumentException.class, () -> c.commit(MazeKnowledge.key(1, 1)));
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
