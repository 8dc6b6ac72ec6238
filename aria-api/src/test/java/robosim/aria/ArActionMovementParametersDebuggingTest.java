package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;

/** ArActionMovementParametersDebugging.cpp's rules: each flagged limit is asked for, as given. */
class ArActionMovementParametersDebuggingTest {
    private final ArActionMovementParametersDebugging params = new ArActionMovementParametersDebugging();

    @Test
    void noFlagNoLimit() {
        assertFalse(ActionFixture.fire(params).isAnythingDesired());
    }

    @Test
    void aFlaggedLimitIsAskedForAsGivenTheOthersNot() {
        params.setMaxVel(true, 300);
        params.setMaxNegVel(true, -150);
        params.setRotDecel(true, 90);
        ArActionDesired d = ActionFixture.fire(params);
        assertEquals(300, d.getMaxVel());
        assertEquals(-150, d.getMaxNegVel());
        assertEquals(90, d.getRotDecel());
        assertEquals(0, d.getTransAccelStrength());
        assertEquals(0, d.getMaxRotVelStrength());
    }

    @Test
    void theParametersAreARIAsConfigEntries() {
        ArArg set = params.getArg(0);
        assertEquals("SetTransVelMax", set.getName());
        assertEquals("TransVelMax", params.getArg(1).getName());
        assertEquals(2000, params.getArg(1).getDouble(), "ARIA's default");
        assertEquals(22, params.getNumArgs());
        params.setMaxLeftLatVel(true, 120);
        assertEquals(120, ActionFixture.fire(params).getMaxLeftLatVel());
    }

    @Test
    void disabledItWantsNothingExceptOnce() {
        params.setTransAccel(true, 200);
        params.disable();
        assertNull(ActionFixture.fire(params));
        params.enableOnceFromSector();
        assertEquals(200, ActionFixture.fire(params).getTransAccel());
        assertNull(ActionFixture.fire(params));
    }
}
