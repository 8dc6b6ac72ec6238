package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robosim.aria.ArActionDeceleratingLimiter.LimiterType;

/**
 * ArActionDeceleratingLimiter.cpp's rules with ARIA's default parameters on a p3dx (511 mm long,
 * 425 wide, decelerating at 300 mm/s²), at the origin facing +x, driving at 300 mm/s: side clearance
 * 93.75 and padding 81.25 (an eighth of the way from slow to fast).
 */
class ArActionDeceleratingLimiterTest {
    private final ActionFixture f = new ActionFixture();
    private final ArActionDeceleratingLimiter limiter = f.attach(new ArActionDeceleratingLimiter());
    private final ArRangeDevice device = new ArRangeDevice("test", 5000);

    @BeforeEach
    void attachADevice() {
        f.robot.addRangeDevice(device);
        f.at(0, 0, 0, 300);
    }

    @Test
    void withRoomEnoughToStopItAsksForNothing() {
        // 600 - 255.5 - 100 - 81.25 = 163.25 mm left; stopping from 300 at 300 mm/s² takes 150
        device.addReading(600, 0);
        assertNull(ActionFixture.fire(limiter));
    }

    @Test
    void shortOfRoomItStopsAndRaisesTheDecelerationToThePreferredOne() {
        // 63.25 mm left: stopping there needs 711 mm/s², within the clearance 311: the preferred 600
        device.addReading(500, 0);
        ArActionDesired d = ActionFixture.fire(limiter);
        assertEquals(0, d.getMaxVel());
        assertEquals(ArActionDesired.MAX_STRENGTH, d.getMaxVelStrength());
        assertEquals(600, d.getTransDecel());
        assertEquals(0, d.getVelStrength(), "it only limits");
    }

    @Test
    void aHigherPriorityDeceleratingHarderAlreadyLeavesTheDecelerationAlone() {
        device.addReading(500, 0);
        ArActionDesired harder = new ArActionDesired();
        harder.setTransDecel(900);
        ArActionDesired d = limiter.fire(harder);
        assertEquals(0, d.getMaxVel());
        assertEquals(0, d.getTransDecelStrength());
    }

    @Test
    void aReadingWithinTheClearanceStopsAtOnce() {
        device.addReading(300, 0);
        ArActionDesired d = ActionFixture.fire(limiter);
        assertEquals(0, d.getMaxVel());
        assertEquals(0, d.getVel());
        assertEquals(ArActionDesired.MAX_STRENGTH, d.getVelStrength());
        assertEquals(600, d.getTransDecel());
        assertTrue(limiter.isStoppedWithinClearance());
    }

    @Test
    void aReadingBesideTheBoxIsNotInTheWay() {
        // 212.5 + 93.75 = 306.25 mm to the side is the box's edge
        device.addReading(500, 320);
        assertNull(ActionFixture.fire(limiter));
    }

    @Test
    void aBackwardsLimiterLooksBehindAndLimitsTheNegativeVelocity() {
        limiter.setType(LimiterType.BACKWARDS);
        device.addReading(500, 0);
        f.at(0, 0, 0, -300);
        assertEquals(null, ActionFixture.fire(limiter), "ahead is not its concern");
        device.addReading(-500, 0);
        ArActionDesired d = ActionFixture.fire(limiter);
        assertEquals(0, d.getMaxNegVel());
        assertEquals(ArActionDesired.MAX_STRENGTH, d.getMaxNegVelStrength());
    }

    @Test
    void goingTheOtherWayFasterThan100ItAsksForNothing() {
        device.addReading(300, 0);
        f.at(0, 0, 0, -150);
        assertNull(ActionFixture.fire(limiter));
    }

    @Test
    void aMaximumEmergencyDecelerationCapsWhatItAsksFor() {
        limiter.setParameters(100, 50, 50, 200, 400, 300, 1000, 600, false, 450);
        device.addReading(300, 0);
        assertEquals(450, ActionFixture.fire(limiter).getTransDecel());
    }

    @Test
    void theBoxTurnsWithTheRobot() {
        f.at(0, 0, 90, 300);
        device.addReading(0, 300);
        assertEquals(0, ActionFixture.fire(limiter).getVel());
    }

    @Test
    void lateralLimitersAskForNothingAsNoRobotMovesSideways() {
        limiter.setType(LimiterType.LATERAL_LEFT);
        device.addReading(0, 300);
        assertNull(ActionFixture.fire(limiter));
    }

    @Test
    void theFastSpeedMustBeAboveTheSlowSpeed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> limiter.setParameters(100, 50, 50, 200, 400, 300, 200, 600, false, 0));
        assertTrue(e.getMessage().contains("fastSpeed"), e.getMessage());
    }
}
