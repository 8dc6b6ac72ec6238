package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** ArActionDesired.h's lateral channels: right is left negated; they merge and are checked like the others. */
class ArActionDesiredLateralTest {
    @Test
    void aRightLateralVelocityIsANegativeLeftOne() {
        ArActionDesired d = new ArActionDesired();
        d.setRightLatVel(120);
        assertEquals(-120, d.getLatVel());
        assertTrue(d.isAnythingDesired());
    }

    @Test
    void theSlowestMaximumLateralVelocityWinsInAMerge() {
        ArActionDesired high = new ArActionDesired();
        high.setMaxLeftLatVel(300);
        ArActionDesired low = new ArActionDesired();
        low.setMaxLeftLatVel(100);
        low.setLatAccel(50);
        high.merge(low);
        assertEquals(100, high.getMaxLeftLatVel());
        assertEquals(50, high.getLatAccel());
    }

    @Test
    void theSanityCheckRaisesALateralAccelerationBelowOne() {
        ArActionDesired d = new ArActionDesired();
        d.setLatAccel(0.2);
        d.setMaxRightLatVel(-5);
        d.sanityCheck("test");
        assertEquals(1, d.getLatAccel());
        assertEquals(0, d.getMaxRightLatVel());
    }

    @Test
    void resetAndCopyCoverThem() {
        ArActionDesired d = new ArActionDesired();
        d.setLatDecel(400);
        assertEquals(400, d.copy().getLatDecel());
        d.reset();
        assertEquals(0, d.getLatDecelStrength());
    }
}
