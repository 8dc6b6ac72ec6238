package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** ArActionTurn.cpp's rules: when it turns, how much, and to which side. */
class ArActionTurnTest {
    private final ActionFixture f = new ActionFixture();
    private final ArActionTurn turn = f.attach(new ArActionTurn());
    private final ArRangeDevice device = new ArRangeDevice("test", 5000);

    @BeforeEach
    void attachADevice() {
        f.robot.addRangeDevice(device);
    }

    @Test
    void fasterThanTheStartSpeedItAsksForNothing() {
        f.at(0, 0, 0, 250);
        assertNull(ActionFixture.fire(turn));
        assertEquals(0, turn.getTurning());
    }

    @Test
    void belowTheFullTurnSpeedWithNothingNearItTurnsTheFullAmountLeft() {
        f.at(0, 0, 0, 50);
        assertEquals(15, ActionFixture.fire(turn).getDeltaHeading());
    }

    @Test
    void betweenTheSpeedsTheTurnGrowsInProportion() {
        f.at(0, 0, 0, 150);
        assertEquals(7.5, ActionFixture.fire(turn).getDeltaHeading(), 1e-9);
    }

    @Test
    void itTurnsAwayFromTheClosestReadingOnTheLeftAndKeepsThatSide() {
        f.at(0, 0, 0, 0);
        device.addReading(800, 500);
        assertEquals(-15, ActionFixture.fire(turn).getDeltaHeading());
        device.clearCurrentReadings();
        device.addReading(800, -500);
        assertEquals(-15, ActionFixture.fire(turn).getDeltaHeading(), "it keeps turning the same way");
        f.at(0, 0, 0, 300);
        ActionFixture.fire(turn);
        f.at(0, 0, 0, 0);
        assertEquals(15, ActionFixture.fire(turn).getDeltaHeading(), "after speeding up it chooses again");
    }

    @Test
    void aReadingThreeMetresAwayOrMoreDoesNotChooseTheSide() {
        f.at(0, 0, 0, 0);
        device.addReading(0, -3000);
        assertEquals(15, ActionFixture.fire(turn).getDeltaHeading());
    }

    @Test
    void theFullTurnSpeedMustBeBelowTheStartSpeed() {
        assertThrows(IllegalArgumentException.class, () -> new ArActionTurn("t", 100, 100, 15));
    }
}
