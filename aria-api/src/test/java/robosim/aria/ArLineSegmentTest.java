package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** ARIA's ArLineSegment: crossings, perpendicular feet and distances. */
class ArLineSegmentTest {
    @Test
    void twoCrossingSegmentsMeetWhereTheyCross() {
        ArLineSegment across = new ArLineSegment(0, 0, 1000, 1000);
        ArPose at = new ArPose();
        assertTrue(across.intersects(new ArLineSegment(0, 1000, 1000, 0), at));
        assertEquals(new ArPose(500, 500), at);
        assertFalse(across.intersects(new ArLineSegment(0, 1000, 400, 600)), "ends short of the crossing");
        assertFalse(across.intersects(new ArLineSegment(0, 100, 1000, 1100)), "parallel");
    }

    @Test
    void thePerpendicularFootMustLieInsideTheSegment() {
        ArLineSegment wall = new ArLineSegment(0, 0, 1000, 0);
        ArPose foot = new ArPose();
        assertTrue(wall.getPerpPoint(new ArPose(300, 400), foot));
        assertEquals(new ArPose(300, 0), foot);
        assertEquals(400, wall.getPerpDist(new ArPose(300, 400)));
        assertEquals(160_000, wall.getPerpSquaredDist(new ArPose(300, -400)));
        assertEquals(-1, wall.getPerpDist(new ArPose(1300, 400)));
        assertEquals(400, wall.getDistToLine(new ArPose(1300, 400)), "the infinite line's distance");
    }

    @Test
    void lengthMidPointAndLineParameters() {
        ArLineSegment s = new ArLineSegment(new ArPose(0, 0), new ArPose(300, 400));
        assertEquals(500, s.getLengthOf());
        assertEquals(new ArPose(150, 200), s.getMidPoint());
        assertEquals(-400, s.getA());
        assertEquals(300, s.getB());
        assertEquals(0, s.getC());
        assertEquals("(0.000000, 0.000000, 300.000000, 400.000000)", s.toString());
        assertTrue(new ArLineSegment(0, 0, 1, 1).compareTo(new ArLineSegment(0, 0, 1, 2)) < 0);
    }

    @Test
    void aOnePointSegmentHoldsOnlyItsPoint() {
        ArLineSegment dot = new ArLineSegment(5, 5, 5, 5);
        assertTrue(dot.linePointIsInSegment(new ArPose(5, 5)));
        assertFalse(dot.linePointIsInSegment(new ArPose(5, 6)));
        assertEquals(5, dot.getDistToLine(new ArPose(8, 9)), "the nearer end, rounded");
    }

    @Test
    void crossingOfLinesOffTheOriginIsOnBothAsInAria2NotAriaCodasSlip() {
        // AriaCoda's ArLine::intersects would put this crossing at x = -500, off both segments
        ArLineSegment across = new ArLineSegment(0, 1000, 2000, 1000);
        ArPose at = new ArPose();
        assertTrue(across.intersects(new ArLineSegment(500, 0, 500, 2000), at));
        assertEquals(new ArPose(500, 1000), at);
        ArPose foot = new ArPose();
        assertTrue(across.getPerpPoint(new ArPose(1500, 1700), foot));
        assertEquals(new ArPose(1500, 1000), foot);
        assertEquals(700, across.getDistToLine(new ArPose(2500, 300)));
    }
}
