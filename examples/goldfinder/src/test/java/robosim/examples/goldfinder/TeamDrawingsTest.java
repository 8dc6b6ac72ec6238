package robosim.examples.goldfinder;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.Figure;

/** What a Gold robot draws: its own cells, every cell it knows, and its claim with the way there. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class TeamDrawingsTest {
    @Test
    void theCellsARobotSensedItselfAreFilledInsetFromTheWalls() {
        List<Figure> f = TeamDrawings.explored(List.of(new int[] {0, 0, 1}, new int[] {2, 1, 4}), 1000);
        assertEquals(Figure.CELLS, f.get(0).kind());
        assertArrayEquals(new double[] {120, 120, 880, 880, 2120, 1120, 2880, 1880}, f.get(0).xy(), 1e-9);
        assertEquals(List.of(), TeamDrawings.explored(List.of(), 1000));
    }

    @Test
    void everyKnownCellIsADotPlacedByTheRobotsNumber() {
        MazeKnowledge map = new MazeKnowledge();
        map.sensed(0, 0, 1);
        map.sensed(1, 0, 4);
        // r1: a tenth of a cell right of r0's place, which is 0.15 cell left of and below the centre
        assertArrayEquals(new double[] {450, 350, 1450, 350}, TeamDrawings.known(map, 1, 1000).get(0).xy(), 1e-9);
        assertArrayEquals(new double[] {350, 450, 1350, 450}, TeamDrawings.known(map, 4, 1000).get(0).xy(), 1e-9);
    }

    @Test
    void aClaimIsASquareAndTheWayThereAFollowedFrontierASmallerSquare() {
        MazeKnowledge map = new MazeKnowledge();
        map.sensed(0, 0, 1);
        map.sensed(1, 0, 4 | 2);
        long frontier = MazeKnowledge.key(1, 1);
        List<Figure> claimed = TeamDrawings.claim(map, 0, 0, new TeamPlan.Plan(frontier, true), 1000);
        assertArrayEquals(new double[] {1300, 1300, 1700, 1700}, claimed.get(0).xy(), 1e-9);
        assertEquals(Figure.LINE, claimed.get(1).kind());
        assertArrayEquals(new double[] {500, 500, 1500, 500, 1500, 1500}, claimed.get(1).xy(), 1e-9);
        List<Figure> followed = TeamDrawings.claim(map, 0, 0, new TeamPlan.Plan(frontier, false), 1000);
        assertArrayEquals(new double[] {1400, 1400, 1600, 1600}, followed.get(0).xy(), 1e-9);
        assertEquals(List.of(), TeamDrawings.claim(map, 0, 0, TeamPlan.Plan.NONE, 1000));
    }
}
