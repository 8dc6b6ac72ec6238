package robosim.examples.goldfinder;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * What a Gold robot knows of the maze, as it records its own and its teammates' reports: sensed
 * cells and their open sides, teammates' places and targets, and the way to the nearest frontier.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class MazeKnowledgeTest {
    private static final int EAST = 0;
    private static final int NORTH = 1;
    private static final int WEST = 2;
    private static final int SOUTH = 3;
    /** Open-side bits, as WallSensing and MazeMessage carry them. */
    private static final int E = 1 << EAST;
    private static final int N = 1 << NORTH;
    private static final int W = 1 << WEST;
    private static final int S = 1 << SOUTH;
    private static final int[] EAST_FIRST = {EAST, NORTH, WEST, SOUTH};
    private static final int[] NORTH_FIRST = {NORTH, WEST, SOUTH, EAST};

    private final MazeKnowledge map = new MazeKnowledge();

    // ---- sensed cells ----

    @Test
    void aSensedCellIsOpenExactlyOnTheSidesOfItsMask() {
        map.sensed(2, 3, E | W);
        assertTrue(map.isSensed(2, 3));
        assertTrue(map.open(2, 3, EAST));
        assertFalse(map.open(2, 3, NORTH));
        assertTrue(map.open(2, 3, WEST));
        assertFalse(map.open(2, 3, SOUTH));
    }

    @Test
    void anUnsensedCellIsOpenNowhere() {
        map.sensed(2, 3, E | N | W | S);
        assertFalse(map.isSensed(3, 3));
        for (int d = 0; d < 4; d++) {
            assertFalse(map.open(3, 3, d), "side " + d + " of a cell nobody sensed");
        }
    }

    @Test
    void aDeadEndSensedWithNoOpenSideCountsAsSensed() {
        map.sensed(4, 0, 0);
        assertTrue(map.isSensed(4, 0));
        for (int d = 0; d < 4; d++) {
            assertFalse(map.open(4, 0, d), "side " + d);
        }
    }

    @Test
    void aLaterReportOfACellReplacesTheEarlierOne() {
        map.sensed(1, 1, E | N);
        map.sensed(1, 1, S);
        assertFalse(map.open(1, 1, EAST));
        assertFalse(map.open(1, 1, NORTH));
        assertTrue(map.open(1, 1, SOUTH));
    }

    @Test
    void cellsWithSwappedOrNegativeCoordinatesAreKeptApart() {
        assertNotEquals(MazeKnowledge.key(1, 2), MazeKnowledge.key(2, 1));
        assertNotEquals(MazeKnowledge.key(-1, 0), MazeKnowledge.key(0, -1));
        assertNotEquals(MazeKnowledge.key(0, -1), MazeKnowledge.key(-1, -1));
        map.sensed(-1, 0, N);
        assertFalse(map.isSensed(0, -1));
        assertTrue(map.open(-1, 0, NORTH));
    }

    @Test
    void aSideIsOpenWhenEitherCellItPartsSaysSo() {
        map.sensed(0, 0, 0);
        map.sensed(1, 0, W);
        assertTrue(map.open(0, 0, EAST), "(1, 0) saw the side open: a teammate passing made it look closed from (0, 0)");
        assertTrue(map.open(1, 0, WEST));
        assertFalse(map.open(0, 0, NORTH));
    }

    // ---- teammates ----

    @Test
    void aMateHoldsTheCellItStandsInAndTheCellsAheadItHasCommittedTo() {
        map.mate("r2", new MazeKnowledge.Mate(1, 1, List.of(MazeKnowledge.key(2, 1), MazeKnowledge.key(2, 2)), 5, 5, 0));
        assertEquals("r2", map.holder(1, 1));
        assertEquals("r2", map.holder(2, 1));
        assertEquals("r2", map.holder(2, 2));
        assertNull(map.holder(5, 5), "a claimed frontier is not held");
        assertEquals(Set.of(MazeKnowledge.key(1, 1), MazeKnowledge.key(2, 1), MazeKnowledge.key(2, 2)), map.held());
    }

    @Test
    void aCellIsHeldAgainstARobotUnlessTheMateInItIsLeavingTheOtherWay() {
        long from = MazeKnowledge.key(0, 1);
        map.mate("r2", new MazeKnowledge.Mate(1, 1, List.of(MazeKnowledge.key(2, 1)), 5, 5, 0));
        assertFalse(map.heldAgainst(MazeKnowledge.key(1, 1), from), "r2 leaves (1, 1) eastwards: follow it in");
        assertTrue(map.heldAgainst(MazeKnowledge.key(2, 1), from), "r2 has committed to (2, 1)");
        map.mate("r2", new MazeKnowledge.Mate(1, 1, List.of(from), 5, 5, 1));
        assertTrue(map.heldAgainst(MazeKnowledge.key(1, 1), from), "r2 comes towards the robot");
        map.mate("r2", new MazeKnowledge.Mate(1, 1, 2));
        assertTrue(map.heldAgainst(MazeKnowledge.key(1, 1), from), "r2 stands in (1, 1)");
        assertFalse(map.heldAgainst(MazeKnowledge.key(3, 3), from));
    }

    @Test
    void aMatesNewReportReplacesItsOldOne() {
        map.mate("r2", new MazeKnowledge.Mate(1, 1, List.of(MazeKnowledge.key(2, 1)), MazeKnowledge.NONE,
                MazeKnowledge.NONE, 3));
        map.mate("r2", new MazeKnowledge.Mate(2, 1, 7));
        assertNull(map.holder(1, 1), "r2 has left (1, 1)");
        assertEquals("r2", map.holder(2, 1));
        assertEquals(new MazeKnowledge.Mate(2, 1, 7), map.mate("r2"));
        assertFalse(map.mate("r2").moving());
        assertFalse(map.mate("r2").claims());
    }

    @Test
    void matesAreListedByNameAndLookedUpByName() {
        map.mate("r3", new MazeKnowledge.Mate(0, 0, 0));
        map.mate("r1", new MazeKnowledge.Mate(1, 0, 0));
        map.mate("r2", new MazeKnowledge.Mate(2, 0, 0));
        assertEquals(List.of("r1", "r2", "r3"), map.mates());
        assertNull(map.mate("r9"));
        assertNull(map.holder(5, 5));
    }

    // ---- frontiers ----

    @Test
    void anUnsensedCellBehindAnOpenSideIsAFrontier() {
        map.sensed(0, 0, E);
        assertTrue(map.isFrontier(1, 0));
        assertEquals(List.of(MazeKnowledge.key(1, 0)), map.frontiers());
    }

    @Test
    void aSensedCellOrOneBehindAWallIsNoFrontier() {
        map.sensed(0, 0, E);
        map.sensed(1, 0, W);
        assertFalse(map.isFrontier(1, 0));
        assertFalse(map.isFrontier(0, 1), "(0, 0) is closed to the north");
        assertEquals(List.of(), map.frontiers());
    }

    // ---- paths ----

    /**
     * A corridor east from (0, 0) to (2, 0), whose north side opens onto unsensed (2, 1); and a
     * shorter way north from (0, 0) to (0, 1), whose north side opens onto unsensed (0, 2).
     */
    private void twoFrontiersOneNearer() {
        map.sensed(0, 0, E | N);
        map.sensed(1, 0, W | E);
        map.sensed(2, 0, W | N);
        map.sensed(0, 1, S | N);
    }

    @Test
    void pathsLeadThroughSensedCellsAndEndInAFrontier() {
        twoFrontiersOneNearer();
        var reach = map.reach(0, 0, EAST_FIRST, Set.of());
        assertEquals(2, reach.get(MazeKnowledge.key(0, 2)).cells());
        assertEquals(NORTH, reach.get(MazeKnowledge.key(0, 2)).first());
        assertEquals(3, reach.get(MazeKnowledge.key(2, 1)).cells());
        assertEquals(EAST, reach.get(MazeKnowledge.key(2, 1)).first());
        assertNull(reach.get(MazeKnowledge.key(0, 3)), "nothing is known beyond a frontier");
        assertEquals(List.of(MazeKnowledge.key(1, 0), MazeKnowledge.key(2, 0), MazeKnowledge.key(2, 1)),
                map.path(0, 0, 2, 1, EAST_FIRST, Set.of()));
    }

    /** A ring of four sensed cells; (1, 1) opens east onto unsensed (2, 1), two cells from (0, 0) either way. */
    private void ringWithAFrontierAtTheFarCorner() {
        map.sensed(0, 0, E | N);
        map.sensed(1, 0, W | N);
        map.sensed(0, 1, S | E);
        map.sensed(1, 1, W | S | E);
    }

    @Test
    void betweenPathsOfEqualLengthTheOrderDecidesAndBlockedCellsAreGoneAround() {
        ringWithAFrontierAtTheFarCorner();
        long corner = MazeKnowledge.key(1, 1);
        assertEquals(EAST, map.reach(0, 0, EAST_FIRST, Set.of()).get(corner).first());
        assertEquals(NORTH, map.reach(0, 0, NORTH_FIRST, Set.of()).get(corner).first());
        assertEquals(NORTH, map.reach(0, 0, EAST_FIRST, Set.of(MazeKnowledge.key(1, 0))).get(corner).first());
        assertNull(map.reach(0, 0, EAST_FIRST, Set.of(MazeKnowledge.key(1, 0), MazeKnowledge.key(0, 1))).get(corner));
    }

    @Test
    void pathsDoNotCrossUnsensedCells() {
        map.sensed(0, 0, E);
        map.sensed(2, 0, W | E);
        assertEquals(List.of(), map.path(0, 0, 3, 0, EAST_FIRST, Set.of()));
    }
}
