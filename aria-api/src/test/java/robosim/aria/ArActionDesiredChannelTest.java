package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** One channel of a desire, as ARIA's ArActionDesiredChannel: its value, strength and override rule. */
class ArActionDesiredChannelTest {
    @Test
    void aSetValueIsAnsweredWithItsStrengthCappedAndTooLittleStrengthIsNone() {
        ArActionDesiredChannel c = new ArActionDesiredChannel();
        assertEquals(ArActionDesiredChannel.NO_STRENGTH, c.getStrength());
        c.setDesired(300, 2, false);
        assertEquals(300, c.getDesired());
        assertEquals(ArActionDesiredChannel.MAX_STRENGTH, c.getStrength());
        assertFalse(c.getAllowOverride());
        c.setDesired(300, ArActionDesiredChannel.MIN_STRENGTH / 2, true);
        assertEquals(ArActionDesiredChannel.NO_STRENGTH, c.getStrength());
        assertTrue(c.getAllowOverride());
    }

    @Test
    void anOverrideKeepsTheLeastOrTheGreatestValue() {
        ArActionDesiredChannel least = new ArActionDesiredChannel();
        least.setDesired(300, 0.5, true);
        ArActionDesiredChannel other = new ArActionDesiredChannel();
        other.setDesired(100, 0.5, true);
        least.merge(other);
        assertEquals(100, least.getDesired());

        ArActionDesiredChannel greatest = new ArActionDesiredChannel();
        greatest.setOverrideDoesLessThan(false);
        greatest.setDesired(300, 0.5, true);
        greatest.merge(other);
        assertEquals(300, greatest.getDesired());
        assertEquals(1, greatest.getStrength());
    }

    @Test
    void withoutOverrideTheAverageIsWeightedByStrength() {
        ArActionDesiredChannel c = new ArActionDesiredChannel();
        c.setDesired(100, 0.25, false);
        c.startAverage();
        ArActionDesiredChannel other = new ArActionDesiredChannel();
        other.setDesired(400, 0.5, false);
        c.addAverage(other);
        c.endAverage();
        assertEquals(300, c.getDesired(), 1e-9, "(0.25 * 100 + 0.5 * 400) / 0.75");
        assertEquals(0.75, c.getStrength(), 1e-9);
    }

    @Test
    void anOverrideAverageTakesTheLesserValueAndIgnoresAChannelWithoutStrength() {
        ArActionDesiredChannel c = new ArActionDesiredChannel();
        c.startAverage();
        ArActionDesiredChannel a = new ArActionDesiredChannel();
        a.setDesired(250, 1, true);
        ArActionDesiredChannel b = new ArActionDesiredChannel();
        b.setDesired(150, 0.5, true);
        c.addAverage(a);
        c.addAverage(b);
        c.addAverage(new ArActionDesiredChannel()); // wants nothing: no part in it
        c.endAverage();
        assertEquals(150, c.getDesired());
        assertEquals(1, c.getStrength(), "capped");
    }
}
