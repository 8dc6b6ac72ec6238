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

    // ---- teammates ----

    @Test
    void aMateClaimsTheCellItStandsInAndTheOneItHeadsFor() {
        map.mate("r2", new MazeKnowledge.Mate(1, 1, 2, 1));
        assertTrue(map.claimedByMate(1, 1));
        assertTrue(map.claimedByMate(2, 1));
        assertFalse(map.claimedByMate(3, 1));
        assertFalse(map.claimedByMate(1, 2));
    }

    @Test
    void aMateWithNoTargetClaimsOnlyItsOwnCell() {
        // Gold reports "no target" as (-1, -1)
        map.mate("r2", new MazeKnowledge.Mate(1, 1, -1, -1));
        assertTrue(map.claimedByMate(1, 1));
        assertFalse(map.claimedByMate(2, 1));
        assertFalse(map.claimedByMate(0, 0));
    }

    @Test
    void aMatesNewReportReplacesItsOldPlaceAndTarget() {
        map.mate("r2", new MazeKnowledge.Mate(1, 1, 2, 1));
        map.mate("r2", new MazeKnowledge.Mate(2, 1, 2, 2));
        assertFalse(map.claimedByMate(1, 1), "r2 has left (1, 1)");
        assertTrue(map.claimedByMate(2, 1));
        assertTrue(map.claimedByMate(2, 2));
        assertEquals(new MazeKnowledge.Mate(2, 1, 2, 2), map.mate("r2"));
    }

    @Test
    void theOccupantIsTheMateStandingInTheCellNotOneHeadingThere() {
        map.mate("r2", new MazeKnowledge.Mate(1, 1, 2, 1));
        map.mate("r3", new MazeKnowledge.Mate(2, 1, -1, -1));
        assertEquals("r3", map.occupant(2, 1));
        assertEquals("r2", map.occupant(1, 1));
        map.mate("r3", new MazeKnowledge.Mate(3, 1, -1, -1));
        assertNull(map.occupant(2, 1), "r2 only heads for (2, 1)");
    }

    @Test
    void matesAreListedByNameAndLookedUpByName() {
        map.mate("r3", new MazeKnowledge.Mate(0, 0, -1, -1));
        map.mate("r1", new MazeKnowledge.Mate(1, 0, -1, -1));
        map.mate("r2", new MazeKnowledge.Mate(2, 0, -1, -1));
        map.mate("r1", new MazeKnowledge.Mate(1, 1, -1, -1));
        assertEquals(List.of("r1", "r2", "r3"), map.mates());
        assertEquals(new MazeKnowledge.Mate(1, 1, -1, -1), map.mate("r1"));
        assertNull(map.mate("r9"));
    }

    @Test
    void noMateHeardFromMeansNoClaimAndNoOccupant() {
        assertEquals(List.of(), map.mates());
        assertFalse(map.claimedByMate(0, 0));
        assertNull(map.occupant(0, 0));
    }

    // ---- frontiers ----

    @Test
    void aSensedCellWithAnOpenSideTowardsAnUnsensedCellHasAFrontier() {
        map.sensed(0, 0, E);
        assertTrue(map.hasFrontier(0, 0));
    }

    @Test
    void aCellWhoseOpenNeighboursAreAllSensedHasNoFrontier() {
        map.sensed(0, 0, E);
        map.sensed(1, 0, W);
        assertFalse(map.hasFrontier(0, 0));
        assertFalse(map.hasFrontier(1, 0));
    }

    @Test
    void aClosedSideTowardsAnUnsensedCellIsNoFrontier() {
        map.sensed(0, 0, 0);
        assertFalse(map.hasFrontier(0, 0));
    }

    @Test
    void anOpenSideTowardsACellAMateClaimedIsNoFrontier() {
        map.sensed(0, 0, E);
        map.mate("r2", new MazeKnowledge.Mate(0, 1, 1, 0));
        assertFalse(map.hasFrontier(0, 0), "r2 is heading for (1, 0)");
        map.mate("r2", new MazeKnowledge.Mate(0, 1, -1, -1));
        assertTrue(map.hasFrontier(0, 0), "r2 has given (1, 0) up");
    }

    @Test
    void anUnsensedCellHasNoFrontier() {
        assertFalse(map.hasFrontier(5, 5));
    }

    // ---- the way to the nearest frontier ----

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
    void theFirstStepLeadsAlongTheShortestKnownPathToTheNearestFrontier() {
        twoFrontiersOneNearer();
        assertEquals(NORTH, map.towardsFrontier(0, 0, EAST_FIRST, Set.of()),
                "(0, 1) is one cell away, (2, 0) two, whichever way is tried first");
    }

    @Test
    void aFrontierFurtherAlongACorridorIsReachedThroughIt() {
        map.sensed(0, 0, E);
        map.sensed(1, 0, W | E);
        map.sensed(2, 0, W | E);
        map.sensed(3, 0, W | N);
        assertEquals(EAST, map.towardsFrontier(0, 0, NORTH_FIRST, Set.of()));
        assertEquals(EAST, map.towardsFrontier(2, 0, NORTH_FIRST, Set.of()));
        assertEquals(-1, map.towardsFrontier(3, 0, NORTH_FIRST, Set.of()),
                "the start's own frontier is no step away");
    }

    /** A ring of four sensed cells; (1, 1) opens east onto unsensed (2, 1), two cells from (0, 0) either way. */
    private void ringWithAFrontierAtTheFarCorner() {
        map.sensed(0, 0, E | N);
        map.sensed(1, 0, W | N);
        map.sensed(0, 1, S | E);
        map.sensed(1, 1, W | S | E);
    }

    @Test
    void betweenPathsOfEqualLengthTheOrderDecides() {
        ringWithAFrontierAtTheFarCorner();
        assertEquals(EAST, map.towardsFrontier(0, 0, EAST_FIRST, Set.of()));
        assertEquals(NORTH, map.towardsFrontier(0, 0, NORTH_FIRST, Set.of()));
    }

    @Test
    void aPathThroughAnAvoidedCellIsNotTaken() {
        ringWithAFrontierAtTheFarCorner();
        assertEquals(NORTH, map.towardsFrontier(0, 0, EAST_FIRST, Set.of(MazeKnowledge.key(1, 0))));
        assertEquals(-1, map.towardsFrontier(0, 0, EAST_FIRST,
                Set.of(MazeKnowledge.key(1, 0), MazeKnowledge.key(0, 1))));
    }

    @Test
    void anAvoidedFrontierCellIsNotATarget() {
        ringWithAFrontierAtTheFarCorner();
        assertEquals(-1, map.towardsFrontier(0, 0, EAST_FIRST, Set.of(MazeKnowledge.key(1, 1))));
    }

    @Test
    void pathsLeadOnlyThroughSensedCells() {
        // (2, 0) has a frontier, but the way there crosses (1, 0), which nobody has sensed
        map.sensed(0, 0, E);
        map.sensed(2, 0, W | E);
        assertEquals(-1, map.towardsFrontier(0, 0, EAST_FIRST, Set.of()));
    }

    @Test
    void aFrontierAMateClaimedIsNoTarget() {
        twoFrontiersOneNearer();
        map.mate("r2", new MazeKnowledge.Mate(0, 1, 0, 2));
        assertEquals(EAST, map.towardsFrontier(0, 0, NORTH_FIRST, Set.of()),
                "r2 heads for (0, 2), so the frontier left is east, at (2, 0)");
    }

    @Test
    void withEverythingExploredThereIsNoWayToAFrontier() {
        map.sensed(0, 0, E);
        map.sensed(1, 0, W);
        assertEquals(-1, map.towardsFrontier(0, 0, EAST_FIRST, Set.of()));
    }
}
