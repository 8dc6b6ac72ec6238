package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** ArActionDriveDistance.cpp's rules: the way travelled, the deceleration profile, backwards, done. */
class ArActionDriveDistanceTest {
    private final ActionFixture f = new ActionFixture();
    private final ArActionDriveDistance drive = f.attach(new ArActionDriveDistance());

    @Test
    void withNoDistanceItAsksForNothing() {
        f.at(0, 0, 0, 0);
        assertNull(ActionFixture.fire(drive));
    }

    @Test
    void itDrivesAtItsSpeedWithNoRotationThenSlowsByItsDeceleration() {
        f.at(0, 0, 0, 0);
        drive.setDistance(1000);
        ArActionDesired d = ActionFixture.fire(drive);
        assertEquals(400, d.getVel());
        assertEquals(0, d.getRotVel());
        assertEquals(ArActionDesired.MAX_STRENGTH, d.getRotVelStrength());
        f.at(900, 0, 0, 300);
        assertEquals(Math.sqrt(100 * 200 * 2), ActionFixture.fire(drive).getVel(), 1e-9);
    }

    @Test
    void theWayIsAddedUpAlongTheTurnsNotMeasuredAsAStraightLine() {
        f.at(0, 0, 0, 0);
        drive.setDistance(1000);
        f.at(400, 0, 0, 300);
        ActionFixture.fire(drive);
        f.at(400, 400, 90, 300);
        ActionFixture.fire(drive);
        f.at(200, 400, 180, 0);
        ActionFixture.fire(drive);
        assertTrue(drive.haveAchievedDistance(), "400 + 400 + 200 mm travelled");
    }

    @Test
    void aNegativeDistanceDrivesBackwards() {
        f.at(0, 0, 0, 0);
        drive.setDistance(-500);
        assertEquals(-400, ActionFixture.fire(drive).getVel());
    }

    @Test
    void itIsDoneOnlyOnceTheRobotHasStopped() {
        f.at(0, 0, 0, 0);
        drive.setDistance(300);
        f.at(300, 0, 0, 50);
        assertEquals(0, ActionFixture.fire(drive).getVel());
        assertFalse(drive.haveAchievedDistance());
        f.at(305, 0, 0, 0);
        ActionFixture.fire(drive);
        assertTrue(drive.haveAchievedDistance());
        assertNull(ActionFixture.fire(drive));
    }

    @Test
    void cancelledItAsksForNothing() {
        f.at(0, 0, 0, 0);
        drive.setDistance(300);
        drive.cancelDistance();
        assertNull(ActionFixture.fire(drive));
        assertFalse(drive.haveAchievedDistance());
    }

    @Test
    void aDistanceNeedsTheRobotAndAPositiveDeceleration() {
        assertThrows(IllegalStateException.class, () -> new ArActionDriveDistance().setDistance(100));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> drive.setDeceleration(0));
        assertTrue(e.getMessage().contains("0.0 was supplied for deceleration of driveDistance"), e.getMessage());
    }
}
