package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import org.junit.jupiter.api.Test;

/** ArActionInput.cpp's rules: the velocity stays, a delta heading is asked for once, clear asks for nothing. */
class ArActionInputTest {
    private final ActionFixture f = new ActionFixture();
    private final ArActionInput input = f.attach(new ArActionInput());

    @Test
    void theVelocityIsAskedForEveryCycle() {
        input.setVel(250);
        assertEquals(250, ActionFixture.fire(input).getVel());
        assertEquals(250, ActionFixture.fire(input).getVel());
    }

    @Test
    void aDeltaHeadingIsAskedForOnceThenZero() {
        input.deltaHeadingFromCurrent(30);
        assertEquals(30, ActionFixture.fire(input).getDeltaHeading());
        assertEquals(0, ActionFixture.fire(input).getDeltaHeading());
    }

    @Test
    void aRotationalVelocityReplacesAHeading() {
        input.setHeading(45);
        assertEquals(45, ActionFixture.fire(input).getHeading());
        input.setRotVel(-20);
        ArActionDesired d = ActionFixture.fire(input);
        assertEquals(-20, d.getRotVel());
        assertEquals(0, d.getHeadingStrength());
    }

    @Test
    void clearAsksForNothing() {
        input.setVel(100);
        input.setRotVel(10);
        input.clear();
        assertFalse(ActionFixture.fire(input).isAnythingDesired());
    }
}
