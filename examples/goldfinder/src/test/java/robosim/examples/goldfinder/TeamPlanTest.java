package robosim.examples.goldfinder;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.examples.goldfinder.MazeKnowledge.NONE;
import static robosim.examples.goldfinder.MazeKnowledge.key;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * How the team divides the maze: claims, who keeps a frontier two robots want, claims that lapse
 * when they are not repeated, and following when nothing is left to claim.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class TeamPlanTest {
    private static final int E = 1;
    private static final int N = 2;
    private static final int W = 4;
    private static final int S = 8;
    private static final int[] EAST_FIRST = {0, 1, 2, 3};
    private static final int[] NORTH_FIRST = {1, 2, 3, 0};

    /**
     * A corridor from (0, 0) east to the junction (1, 0), which opens north onto (1, 1) and east
     * onto (2, 0), neither sensed: two open branches.
     */
    private static MazeKnowledge junction() {
        MazeKnowledge map = new MazeKnowledge();
        map.sensed(0, 0, E);
        map.sensed(1, 0, W | N | E);
        return map;
    }

    /** What a robot hears when a teammate tells it where it is and what it claimed. */
    private static MazeKnowledge.Mate claiming(int x, int y, long claim, long heard) {
        return new MazeKnowledge.Mate(x, y, List.of(), MazeKnowledge.keyX(claim), MazeKnowledge.keyY(claim), heard);
    }

    @Test
    void twoRobotsAtAJunctionWithTwoOpenBranchesTakeDifferentBranches() {
        // r1 stands in the junction, r2 behind it; both prefer the same branch first (east)
        MazeKnowledge r1 = junction();
        MazeKnowledge r2 = junction();
        TeamPlan.Plan first = TeamPlan.plan(r1, 1, 1, 0, EAST_FIRST, 10);
        assertTrue(first.claim());
        r2.mate("r1", claiming(1, 0, first.target(), 10));
        r1.mate("r2", new MazeKnowledge.Mate(0, 0, 10));
        TeamPlan.Plan second = TeamPlan.plan(r2, 2, 0, 0, EAST_FIRST, 11);
        assertTrue(second.claim(), "the other branch is free for r2 to claim");
        assertNotEquals(first.target(), second.target(), "r1 took " + first + ", r2 must take the other branch");
        assertEquals(java.util.Set.of(key(2, 0), key(1, 1)), java.util.Set.of(first.target(), second.target()));
    }

    @Test
    void whenBothClaimOneFrontierAtOnceTheNearerKeepsItOnBothSides() {
        MazeKnowledge r1 = junction();
        MazeKnowledge r2 = junction();
        // both claimed (2, 0) before hearing each other: r2 stands in the junction, one cell nearer
        r1.mate("r2", claiming(1, 0, key(2, 0), 5));
        r2.mate("r1", claiming(0, 0, key(2, 0), 5));
        assertTrue(TeamPlan.wins(r2, 2, 1, key(2, 0), 6), "r2 is one cell from (2, 0), r1 two");
        assertFalse(TeamPlan.wins(r1, 1, 2, key(2, 0), 6));
        TeamPlan.Plan r1Next = TeamPlan.plan(r1, 1, 0, 0, EAST_FIRST, 6);
        assertEquals(key(1, 1), r1Next.target(), "r1 gives (2, 0) up for the other branch");
    }

    @Test
    void betweenClaimantsAsNearTheLowerNumberKeepsTheFrontier() {
        MazeKnowledge map = junction();
        map.mate("r1", claiming(1, 0, key(2, 0), 5));
        assertFalse(TeamPlan.wins(map, 2, 1, key(2, 0), 6), "as near as r1, and r2 goes after r1");
        MazeKnowledge other = junction();
        other.mate("r3", claiming(1, 0, key(2, 0), 5));
        assertTrue(TeamPlan.wins(other, 2, 1, key(2, 0), 6), "as near as r3, and r2 goes first");
    }

    @Test
    void aClaimNotRepeatedLapsesSoItsBranchIsNotLeftUnexploredForever() {
        // r1 claimed the north branch, then went silent: its later messages were lost, or it failed
        MazeKnowledge map = junction();
        map.sensed(2, 0, W); // the east branch is a dead end, explored
        map.mate("r1", claiming(1, 0, key(1, 1), 100));
        assertEquals(new TeamPlan.Plan(key(1, 1), false), TeamPlan.plan(map, 2, 0, 0, EAST_FIRST, 100 + TeamPlan.CLAIM_STEPS),
                "while the claim is fresh, r2 only follows r1 there");
        TeamPlan.Plan later = TeamPlan.plan(map, 2, 0, 0, EAST_FIRST, 101 + TeamPlan.CLAIM_STEPS);
        assertEquals(new TeamPlan.Plan(key(1, 1), true), later, "the lapsed claim is r2's to take");
    }

    @Test
    void aFrontierATeammateHasCommittedToIsNotClaimed() {
        MazeKnowledge map = junction();
        map.mate("r1", new MazeKnowledge.Mate(1, 0, List.of(key(2, 0)), NONE, NONE, 5));
        TeamPlan.Plan p = TeamPlan.plan(map, 2, 0, 0, EAST_FIRST, 6);
        assertEquals(new TeamPlan.Plan(key(1, 1), true), p);
    }

    @Test
    void aTeammatesWayIsCountedThroughTheCellsItHasCommittedTo() {
        // a corridor from the frontier (0, 0) east to the dead end (4, 0)
        MazeKnowledge map = new MazeKnowledge();
        map.sensed(1, 0, W | E);
        map.sensed(2, 0, W | E);
        map.sensed(3, 0, W | E);
        map.sensed(4, 0, W);
        map.mate("r1", claiming(2, 0, key(0, 0), 5));
        assertEquals(2, TeamPlan.cellsTo(map, map.mate("r1"), key(0, 0)));
        assertFalse(TeamPlan.wins(map, 2, 3, key(0, 0), 6), "r1 stands two cells from it, r2 three");
        // r1 has committed to drive on east to (3, 0): it gets to the frontier after r2
        map.mate("r1", new MazeKnowledge.Mate(2, 0, List.of(key(3, 0)), 0, 0, 5));
        assertEquals(4, TeamPlan.cellsTo(map, map.mate("r1"), key(0, 0)));
        assertTrue(TeamPlan.wins(map, 2, 3, key(0, 0), 6));
    }

    @Test
    void aRobotWithNothingToClaimFollowsAClaimNoNearerTeammateFollows() {
        // r1 and r3 stand in the junction and claim a branch each; r2, behind, can claim neither
        MazeKnowledge map = junction();
        map.mate("r1", claiming(1, 0, key(2, 0), 5));
        map.mate("r3", claiming(1, 0, key(1, 1), 5));
        assertEquals(new TeamPlan.Plan(key(2, 0), false), TeamPlan.plan(map, 2, 0, 0, EAST_FIRST, 6),
                "both branches as near: the direction order decides");
        // r4, in the junction too, already follows r1 east
        map.mate("r4", new MazeKnowledge.Mate(1, 0, List.of(), NONE, NONE, 5, -1, key(2, 0)));
        assertEquals(new TeamPlan.Plan(key(1, 1), false), TeamPlan.plan(map, 2, 0, 0, EAST_FIRST, 6),
                "r4 is at hand where r1's branch forks; r2 follows r3");
    }

    @Test
    void withNothingLeftToExploreThereIsNoPlan() {
        MazeKnowledge map = new MazeKnowledge();
        map.sensed(0, 0, E);
        map.sensed(1, 0, W);
        assertEquals(TeamPlan.Plan.NONE, TeamPlan.plan(map, 1, 0, 0, EAST_FIRST, 0));
    }

    @Test
    void betweenFrontiersAsNearTheRobotsOwnDirectionOrderDecides() {
        MazeKnowledge map = junction();
        assertEquals(key(2, 0), TeamPlan.plan(map, 1, 1, 0, EAST_FIRST, 0).target());
        assertEquals(key(1, 1), TeamPlan.plan(map, 1, 1, 0, NORTH_FIRST, 0).target());
    }

    @Test
    void theFirstStepGoesAroundATeammateWhenThereIsAWayAround() {
        // a ring: (0, 0) (1, 0) (1, 1) (0, 1); (1, 1) opens east onto the frontier (2, 1)
        MazeKnowledge map = new MazeKnowledge();
        map.sensed(0, 0, E | N);
        map.sensed(1, 0, W | N);
        map.sensed(0, 1, S | E);
        map.sensed(1, 1, W | S | E);
        assertEquals(0, TeamPlan.firstStep(map, 0, 0, key(2, 1), EAST_FIRST));
        map.mate("r2", new MazeKnowledge.Mate(1, 0, 3));
        assertEquals(1, TeamPlan.firstStep(map, 0, 0, key(2, 1), EAST_FIRST), "r2 stands in (1, 0): go north");
        map.mate("r3", new MazeKnowledge.Mate(0, 1, 3));
        assertEquals(0, TeamPlan.firstStep(map, 0, 0, key(2, 1), EAST_FIRST),
                "no way around both: the shortest way, to wait there");
    }
}
