package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * ArActionDesired's rotational limits and accelerations (ARIA's ArActionDesired.h): by default the
 * slowest limit and acceleration win and the fastest deceleration does, across priorities and
 * within one; asked not to, they are averaged by strength. And the averaging of one priority's
 * desires that ARIA's priority resolver does.
 */
class ArActionDesiredRotationTest {
    private static ArActionDesired merged(ArActionDesired high, ArActionDesired low) {
        ArActionDesired d = high.copy();
        d.merge(low);
        return d;
    }

    @Test
    void theSlowestMaximumRotationalVelocityWinsEachWay() {
        ArActionDesired high = new ArActionDesired();
        high.setMaxRotVel(40);
        high.setMaxRotVelPos(30);
        high.setMaxRotVelNeg(20);
        ArActionDesired low = new ArActionDesired();
        low.setMaxRotVel(25);
        low.setMaxRotVelPos(35);
        low.setMaxRotVelNeg(10);
        assertTrue(high.getMaxRotVelSlowestUsed() && high.getMaxRotVelPosSlowestUsed()
                && high.getMaxRotVelNegSlowestUsed(), "ARIA's default");
        ArActionDesired d = merged(high, low);
        assertEquals(25, d.getMaxRotVel());
        assertEquals(30, d.getMaxRotVelPos());
        assertEquals(10, d.getMaxRotVelNeg());
        assertEquals(ArActionDesired.MAX_STRENGTH, d.getMaxRotVelStrength());
        assertEquals(ArActionDesired.MAX_STRENGTH, d.getMaxRotVelPosStrength());
        assertEquals(ArActionDesired.MAX_STRENGTH, d.getMaxRotVelNegStrength());
    }

    @Test
    void withoutSlowestTheLimitsAreAveragedByStrength() {
        ArActionDesired high = new ArActionDesired();
        high.setMaxRotVel(40, 0.5, false);
        high.setMaxRotVelPos(30, 0.25, false);
        high.setMaxRotVelNeg(20, 0.5, false);
        assertFalse(high.getMaxRotVelSlowestUsed());
        assertFalse(high.getMaxRotVelPosSlowestUsed());
        assertFalse(high.getMaxRotVelNegSlowestUsed());
        ArActionDesired low = new ArActionDesired();
        low.setMaxRotVel(10, 0.5);
        low.setMaxRotVelPos(60, 0.5);
        low.setMaxRotVelNeg(50);
        ArActionDesired d = merged(high, low);
        assertEquals(25, d.getMaxRotVel(), 1e-9, "(0.5 * 40 + 0.5 * 10) / 1");
        assertEquals(50, d.getMaxRotVelPos(), 1e-9, "(0.25 * 30 + 0.5 * 60) / 0.75");
        assertEquals(0.75, d.getMaxRotVelPosStrength(), 1e-9);
        assertEquals(35, d.getMaxRotVelNeg(), 1e-9, "the lower priority gets only the strength left: 0.5");
        assertEquals(1, d.getMaxRotVelNegStrength(), 1e-9);
    }

    @Test
    void theSlowestAccelerationAndTheFastestDecelerationWin() {
        ArActionDesired high = new ArActionDesired();
        high.setRotAccel(100);
        high.setRotDecel(100);
        high.setTransAccel(300);
        ArActionDesired low = new ArActionDesired();
        low.setRotAccel(50);
        low.setRotDecel(200);
        low.setTransAccel(200);
        assertTrue(high.getRotAccelSlowestUsed());
        assertTrue(high.getRotDecelFastestUsed());
        assertTrue(high.getTransAccelSlowestUsed());
        ArActionDesired d = merged(high, low);
        assertEquals(50, d.getRotAccel());
        assertEquals(200, d.getRotDecel(), "stopping harder is the safer choice");
        assertEquals(200, d.getTransAccel());
        assertEquals(1, d.getRotAccelStrength());
        assertEquals(1, d.getRotDecelStrength());
        assertEquals(1, d.getTransAccelStrength());
    }

    @Test
    void theUsedFlagsFollowTheLastSetting() {
        ArActionDesired d = new ArActionDesired();
        d.setMaxVel(300, 1, false);
        d.setMaxNegVel(-300, 1, false);
        d.setTransAccel(200, 1, false);
        d.setTransDecel(200, 1, false);
        d.setRotAccel(50, 1, false);
        d.setRotDecel(50, 1, false);
        assertFalse(d.getMaxVelSlowestUsed());
        assertFalse(d.getMaxNegVelSlowestUsed());
        assertFalse(d.getTransAccelSlowestUsed());
        assertFalse(d.getTransDecelFastestUsed());
        assertFalse(d.getRotAccelSlowestUsed());
        assertFalse(d.getRotDecelFastestUsed());
        d.reset();
        assertTrue(d.getMaxVelSlowestUsed(), "reset: back to ARIA's default");
    }

    @Test
    void averagingOnePrioritysDesiresWeighsTheVelocitiesAndKeepsTheSlowestLimit() {
        ArActionDesired a = new ArActionDesired();
        a.setVel(200);
        a.setMaxRotVel(30);
        a.setDeltaHeading(10, 0.5);
        ArActionDesired b = new ArActionDesired();
        b.setVel(100, 0.5);
        b.setMaxRotVel(20);
        b.setDeltaHeading(40, 0.5);
        ArActionDesired avg = new ArActionDesired();
        avg.startAverage();
        avg.addAverage(a);
        avg.addAverage(b);
        avg.addAverage(null);
        avg.endAverage();
        assertEquals(500.0 / 3, avg.getVel(), 1e-9, "(1 * 200 + 0.5 * 100) / 1.5");
        assertEquals(1, avg.getVelStrength(), "the strengths add up to at most 1");
        assertEquals(20, avg.getMaxRotVel());
        assertEquals(25, avg.getDeltaHeading(), 1e-9);
        assertEquals(1, avg.getDeltaHeadingStrength(), 1e-9);
    }

    @Test
    void anAverageOfNothingDesiresNothing() {
        ArActionDesired avg = new ArActionDesired();
        avg.startAverage();
        avg.addAverage(new ArActionDesired());
        avg.endAverage();
        assertFalse(avg.isAnythingDesired());
    }
}
