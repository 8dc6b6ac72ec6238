package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** ArActionGoto.cpp's rules: the speed profile, the close distance, turning when slowed, cancelling. */
class ArActionGotoTest {
    private final ActionFixture f = new ActionFixture();
    private final ArActionGoto go = f.attach(new ArActionGoto("goto", new ArPose(2000, 0, 0), 100, 400, 150, 7));

    @Test
    void farFromTheGoalItPointsAtItAndDrivesAtItsSpeed() {
        f.at(0, 0, 0, 0);
        ArActionDesired d = ActionFixture.fire(go);
        assertEquals(400, d.getVel());
        assertEquals(0, d.getHeading());
        assertEquals(ArActionDesired.MAX_STRENGTH, d.getHeadingStrength());
    }

    @Test
    void nearTheGoalItSlowsAsTheSquareRootOfTwiceTwoHundredTimesTheDistance() {
        f.at(1800, 0, 0, 300);
        assertEquals(Math.sqrt(200 * 400), ActionFixture.fire(go).getVel(), 1e-9);
    }

    @Test
    void theGoalToTheLeftIsAnAbsoluteHeadingOfNinety() {
        go.setGoal(new ArPose(0, 1000, 0));
        f.at(0, 0, 0, 0);
        assertEquals(90, ActionFixture.fire(go).getHeading(), 1e-9);
    }

    @Test
    void withinTheCloseDistanceButMovingItAsksForZeroAndIsNotThereYet() {
        f.at(1950, 0, 0, 100);
        assertEquals(0, ActionFixture.fire(go).getVel());
        assertFalse(go.haveAchievedGoal());
    }

    @Test
    void withinTheCloseDistanceAndStoppedTheGoalIsAchievedAndItAsksForNothingMore() {
        f.at(1950, 0, 0, 2);
        ArActionDesired d = ActionFixture.fire(go);
        assertEquals(0, d.getVel());
        assertEquals(0, d.getDeltaHeading());
        assertTrue(go.haveAchievedGoal());
        assertNull(ActionFixture.fire(go));
    }

    @Test
    void whenAHigherPriorityHoldsItBelowTheSpeedToTurnAtItTurnsByTheTurnAmount() {
        f.at(0, 0, 0, 100);
        ArActionDesired slowed = new ArActionDesired();
        slowed.setMaxVel(100);
        assertEquals(7, go.fire(slowed).getDeltaHeading());
    }

    @Test
    void aGoalMoreThan120DegreesOffFlipsTheSideItTurnsTo() {
        go.setGoal(new ArPose(-2000, 0, 0));
        f.at(0, 0, 0, 100);
        ArActionDesired slowed = new ArActionDesired();
        slowed.setMaxVel(100);
        assertEquals(-7, go.fire(slowed).getDeltaHeading());
    }

    @Test
    void aCancelledGoalAsksForNothing() {
        go.cancelGoal();
        f.at(0, 0, 0, 0);
        assertNull(ActionFixture.fire(go));
        assertFalse(go.haveAchievedGoal());
    }

    @Test
    void aNewGoalStartsItGoingAgain() {
        f.at(1950, 0, 0, 0);
        ActionFixture.fire(go);
        go.setGoal(new ArPose(5000, 0, 0));
        assertFalse(go.haveAchievedGoal());
        assertEquals(400, ActionFixture.fire(go).getVel());
        assertEquals(5000, go.getGoal().getX());
    }

    @Test
    void ariasDefaults() {
        ArActionGoto d = new ArActionGoto();
        assertEquals("goto", d.getName());
        assertEquals(100, d.getCloseDist());
        assertEquals(400, d.getSpeed());
        assertEquals(0, d.getGoal().getX());
    }

    @Test
    void aNegativeCloseDistanceIsRefusedByName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> go.setCloseDist(-5));
        assertTrue(e.getMessage().contains("-5.0 was supplied for closeDist of goto"), e.getMessage());
    }
}
