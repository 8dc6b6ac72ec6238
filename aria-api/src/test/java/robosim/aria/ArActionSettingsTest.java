package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The settings ARIA's actions take after they are made, and what each then wants: a constant
 * velocity's speed, a keydrive's speeds and steps, a decelerating limiter's rotation stop, a
 * drive-distance's distance, and a forwards limiter's stop (ArActionLimiterForwards.cpp). Each
 * action's {@code getDesired} is what its last firing returned.
 */
class ArActionSettingsTest {
    private final ActionFixture f = new ActionFixture();

    @Test
    void aConstantVelocityDrivesStraightAtTheVelocityItWasLastGiven() {
        ArActionConstantVelocity cv = f.attach(new ArActionConstantVelocity());
        assertEquals(400, cv.getVelocity(), "ARIA's default");
        cv.setVelocity(250);
        assertEquals(250, cv.getVelocity());
        f.at(0, 0, 0, 0);
        ArActionDesired d = ActionFixture.fire(cv);
        assertEquals(250, d.getVel());
        assertEquals(0, d.getDeltaHeading());
        assertEquals(ArActionDesired.MAX_STRENGTH, d.getDeltaHeadingStrength(), "straight, at full strength");
        assertSame(d, cv.getDesired());
    }

    @Test
    void aKeydrivesSpeedsAndStepsCanBeChangedAndItRemembersTheSpeedItAskedFor() {
        ArActionKeydrive keys = f.attach(new ArActionKeydrive());
        keys.setIncrements(100, 5);
        keys.setSpeeds(150, 8);
        f.at(0, 0, 0, 0);
        keys.up();
        keys.up();
        keys.left();
        keys.left();
        ArActionDesired d = ActionFixture.fire(keys);
        assertEquals(150, d.getVel(), "two steps of 100, within the top speed of 150");
        assertEquals(150, keys.getDesiredSpeed());
        assertEquals(8, d.getDeltaHeading(), "two steps of 5, within the largest turn of 8");
        assertSame(d, keys.getDesired());
        assertThrows(IllegalArgumentException.class, () -> keys.setSpeeds(-1, 8));
        assertThrows(IllegalArgumentException.class, () -> keys.setIncrements(10, -1));
        keys.deactivate();
        assertEquals(0, keys.getDesiredSpeed(), "switched off, it forgets its speed");
    }

    @Test
    void aDeceleratingLimiterStopsTheRotationTooOnlyWhenAsked() {
        ArActionDeceleratingLimiter limiter = f.attach(new ArActionDeceleratingLimiter());
        ArRangeDevice device = new ArRangeDevice("test", 5000);
        f.robot.addRangeDevice(device);
        f.at(0, 0, 0, 300);
        device.addReading(300, 0); // within the clearance
        assertEquals(0, ActionFixture.fire(limiter).getRotVelStrength(), "ARIA's default: rotation left alone");
        limiter.setStopRotationToo(true);
        ArActionDesired d = ActionFixture.fire(limiter);
        assertEquals(0, d.getRotVel());
        assertEquals(ArActionDesired.MAX_STRENGTH, d.getRotVelStrength());
        assertSame(d, limiter.getDesired());
        assertTrue(limiter.getUseLocationDependentDevices(), "ARIA's default");
        limiter.setUseLocationDependentDevices(false);
        assertFalse(limiter.getUseLocationDependentDevices());
    }

    @Test
    void aDriveDistanceAnswersItsDistanceHowItIsMeasuredAndItsDeceleration() {
        ArActionDriveDistance drive = f.attach(new ArActionDriveDistance("drive", 300, 250));
        assertEquals(250, drive.getDeceleration());
        f.at(0, 0, 0, 0);
        drive.setDistance(800);
        assertEquals(800, drive.getDistance());
        assertTrue(drive.usingEncoders(), "ARIA's default");
        drive.setDistance(-500, false);
        assertEquals(-500, drive.getDistance());
        assertFalse(drive.usingEncoders());
        ArActionDesired d = ActionFixture.fire(drive);
        assertEquals(-300, d.getVel(), "backwards, at its speed: stopping from it takes less than 500 mm");
        assertSame(d, drive.getDesired());
    }

    @Test
    void aForwardsLimiterStopsInsideItsStopDistanceSlowsBeforeItAndRemembersTheReading() {
        ArActionLimiterForwards limiter = f.attach(new ArActionLimiterForwards("limit", 250, 1000, 200, 1));
        ArRangeDevice device = new ArRangeDevice("test", 5000);
        f.robot.addRangeDevice(device);
        f.at(0, 0, 0, 0);
        device.addReading(2000, 0);
        assertNull(ActionFixture.fire(limiter), "nothing within the slow distance");
        assertFalse(limiter.getStopped());

        device.clearCurrentReadings();
        device.addReading(255.5 + 625, 0); // 625 mm ahead of the front: halfway from stop to slow
        ArActionDesired slow = ActionFixture.fire(limiter);
        assertEquals(100, slow.getMaxVel(), 1e-9);
        assertFalse(limiter.getStopped());

        device.clearCurrentReadings();
        device.addReading(255.5 + 100, 30);
        assertEquals(0, ActionFixture.fire(limiter).getMaxVel());
        assertTrue(limiter.getStopped());
        assertEquals(355.5, limiter.getLastSensorReadingPos().getX(), 1e-9);
        assertEquals(30, limiter.getLastSensorReadingPos().getY(), 1e-9);
        assertSame(limiter.getDesired(), ActionFixture.fire(limiter));
    }

    @Test
    void activateAndTheDefaultActivationState() {
        ArActionStop stop = new ArActionStop();
        assertTrue(ArAction.getDefaultActivationState(), "ARIA's default: actions start active");
        stop.deactivate();
        stop.activate();
        assertTrue(stop.isActive());
        ArAction.setDefaultActivationState(false);
        try {
            assertFalse(new ArActionStop().isActive());
            assertFalse(ArAction.getDefaultActivationState());
        } finally {
            ArAction.setDefaultActivationState(true);
        }
        assertTrue(new ArActionStop().isActive());
    }

    @Test
    void aGroupActivatesItsOwnAndRemovesThemFromTheRobot() {
        ArActionGroup group = new ArActionGroup(f.robot);
        ArActionStop stop = new ArActionStop("stop");
        ArActionConstantVelocity go = new ArActionConstantVelocity("go", 200);
        f.robot.addAction(go, 10);
        group.addAction(stop, 50);
        f.robot.deactivateActions();
        group.activate();
        assertTrue(stop.isActive());
        assertFalse(go.isActive(), "the robot's other actions stay as they are");

        group.removeActions();
        assertNull(f.robot.findAction("stop"));
        assertSame(go, f.robot.findAction("go"));
        assertEquals(List.of(stop), group.getActionList(), "the group still lists it");
    }

    @Test
    void aStopAndAnInputKeepTheDesireOfTheirLastFiring() {
        f.at(0, 0, 0, 0);
        ArActionStop stop = f.attach(new ArActionStop());
        ArActionDesired stopping = ActionFixture.fire(stop);
        assertSame(stopping, stop.getDesired());
        assertEquals(0, stop.getDesired().getVel());
        assertEquals(ArActionDesired.MAX_STRENGTH, stop.getDesired().getVelStrength());

        ArActionInput input = f.attach(new ArActionInput());
        input.setVel(120);
        input.setRotVel(15);
        assertSame(ActionFixture.fire(input), input.getDesired());
        assertEquals(120, input.getDesired().getVel());
        assertEquals(15, input.getDesired().getRotVel());
        input.clear();
        ActionFixture.fire(input);
        assertFalse(input.getDesired().isAnythingDesired(), "cleared: it wants nothing");
    }
}
