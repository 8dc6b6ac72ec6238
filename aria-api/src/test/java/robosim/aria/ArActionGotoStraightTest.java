package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** ArActionGotoStraight.cpp's rules: heading and speed to the goal, backing, just-distance, turning in place. */
class ArActionGotoStraightTest {
    private final ActionFixture f = new ActionFixture();
    private final ArActionGotoStraight go = f.attach(new ArActionGotoStraight("gotostraight", 400));

    @Test
    void withNoGoalItAsksForNothing() {
        f.at(0, 0, 0, 0);
        assertNull(ActionFixture.fire(go));
    }

    @Test
    void itAsksForTheHeadingToTheGoalAndItsSpeed() {
        f.at(0, 0, 0, 0);
        go.setGoal(new ArPose(1000, 1000, 0));
        ArActionDesired d = ActionFixture.fire(go);
        assertEquals(45, d.getHeading(), 1e-9);
        assertEquals(400, d.getVel());
    }

    @Test
    void backingItFacesAwayAndDrivesBackwards() {
        f.at(0, 0, 0, 0);
        go.setGoal(new ArPose(-1000, 0, 0), true, true);
        ArActionDesired d = ActionFixture.fire(go);
        assertEquals(0, d.getHeading(), 1e-9);
        assertEquals(-400, d.getVel());
        assertTrue(go.getBacking());
    }

    @Test
    void inJustDistanceModeItIsDoneAfterTheDistanceAndStopped() {
        f.at(0, 0, 0, 0);
        go.setGoal(new ArPose(1000, 0, 0));
        f.at(600, 0, 0, 300);
        assertEquals(Math.sqrt(400 * 400), ActionFixture.fire(go).getVel(), 1e-9);
        f.at(1000, 40, 0, 100);
        assertEquals(0, ActionFixture.fire(go).getVel());
        assertFalse(go.haveAchievedGoal());
        f.at(1000, 40, 0, 0);
        ActionFixture.fire(go);
        assertTrue(go.haveAchievedGoal());
        assertNull(ActionFixture.fire(go));
    }

    @Test
    void notInJustDistanceModeItIsDoneWithinTheCloseDistance() {
        f.at(0, 0, 0, 0);
        go.setGoal(new ArPose(1000, 0, 0), false, false);
        go.setCloseDist(60);
        f.at(930, 0, 0, 0);
        ActionFixture.fire(go);
        assertFalse(go.haveAchievedGoal(), "70 mm is not within 60");
        f.at(950, 0, 0, 0);
        ActionFixture.fire(go);
        assertTrue(go.haveAchievedGoal());
    }

    @Test
    void aRelativeGoalIsTakenFromTheRobotsPoseAndHeading() {
        f.at(100, 200, 90, 0);
        go.setGoalRel(1000, 90);
        assertEquals(-900, go.getGoal().getX(), 1e-9);
        assertEquals(200, go.getGoal().getY(), 1e-9);
    }

    @Test
    void aboveTheTurnThresholdItTurnsInPlaceAtTheTurnSpeed() {
        f.at(0, 0, 0, 0);
        go.setGoal(new ArPose(0, 1000, 0));
        go.setTurnThreshold(30);
        go.setTurnSpeed(50);
        ArActionDesired d = ActionFixture.fire(go);
        assertEquals(90, d.getHeading(), 1e-9);
        assertEquals(0, d.getVelStrength(), "no forward motion yet");
        assertEquals(50, d.getMaxRotVel());
    }

    @Test
    void whileDrivingTheRotationIsLimitedToTheMaxRotVelAndZeroMeansTheRobotsOwn() {
        f.at(0, 0, 0, 0);
        go.setGoal(new ArPose(1000, 0, 0));
        go.setMaxRotVel(20);
        ArActionDesired d = ActionFixture.fire(go);
        assertEquals(400, d.getVel());
        assertEquals(20, d.getMaxRotVel());
        assertEquals(ArActionDesired.MAX_STRENGTH, d.getMaxRotVelStrength());
        go.setMaxRotVel(0);
        f.at(10, 0, 0, 100);
        assertEquals(0, ActionFixture.fire(go).getMaxRotVelStrength(), "no limit of its own");
        assertThrows(IllegalArgumentException.class, () -> go.setMaxRotVel(-1));
    }

    @Test
    void eachFiringWantsOnlyWhatThisCycleNeedsAsAriasResetDesireDoes() {
        f.at(0, 0, 0, 0);
        go.setGoal(new ArPose(1000, 0, 0));
        go.setTurnThreshold(30);
        go.setMaxRotVel(20);
        ArActionDesired driving = ActionFixture.fire(go);
        assertEquals(400, driving.getVel());
        f.at(10, 0, 90, 0); // turned away: the goal is now 90 degrees off
        ArActionDesired turning = ActionFixture.fire(go);
        assertEquals(0, turning.getVelStrength(), "turning in place: the last cycle's speed is not wanted again");
        assertEquals(0, turning.getMaxRotVelStrength(), "nor the driving limit, with no turn speed set");
        assertEquals(0, turning.getHeading(), 1e-6, "towards the goal, along +x");
        assertSame(turning, go.getDesired(), "getDesired is the last firing's desire");
    }

    @Test
    void aGoalNeedsTheRobot() {
        ArActionGotoStraight loose = new ArActionGotoStraight();
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> loose.setGoal(new ArPose()));
        assertTrue(e.getMessage().contains("addAction"), e.getMessage());
    }
}
