package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** ArActionRatioInput.cpp's rules: ratios to velocities, dead zones, throttle, callbacks. */
class ArActionRatioInputTest {
    private final ArRobot robot = Cycles.p3dxRobot();
    private final ArActionRatioInput input = new ArActionRatioInput();
    private long time;
    private double transMax;

    private void moving(double vel, double rotVel) {
        time += 100;
        Cycles.cycleMoving(robot, time, vel, rotVel);
    }

    @BeforeEach
    void attach() {
        input.setRobot(robot);
        moving(0, 0);
        transMax = robot.getTransVelMax();
        assertTrue(transMax > 0);
    }

    @Test
    void fullForwardsAtFullThrottleIsTheRobotsMaximumScaledByBothRatios() {
        input.setRatios(100, 0, 100);
        assertEquals(transMax, ActionFixture.fire(input).getVel(), 1e-9);
        input.setRatios(50, 0, 50);
        assertEquals(transMax / 4, ActionFixture.fire(input).getVel(), 1e-9);
    }

    @Test
    void fullBackwardsIsAQuarterOfTheMaximumUnlessSet() {
        input.setRatios(-100, 0, 100);
        assertEquals(-transMax / 4, ActionFixture.fire(input).getVel(), 1e-9);
        input.setParameters(500, 300, 25, 25, 50);
        assertEquals(-300, ActionFixture.fire(input).getVel(), 1e-9);
    }

    @Test
    void insideTheDeadZonesItAsksForNoMotion() {
        input.setRatios(9, 4, 100);
        ArActionDesired d = ActionFixture.fire(input);
        assertEquals(0, d.getVel());
        assertEquals(1, d.getVelStrength());
        assertEquals(0, d.getRotVel());
        assertEquals(1, d.getRotVelStrength());
    }

    @Test
    void stoppedItTurnsAtTheRotationWhenStoppedScaledByRatioAndThrottle() {
        input.setRatios(0, 100, 50);
        assertEquals(25, ActionFixture.fire(input).getRotVel(), 1e-9);
        input.setRatios(0, -60, 100);
        assertEquals(-30, ActionFixture.fire(input).getRotVel(), 1e-9);
    }

    @Test
    void drivingTheRotationGoesFromTheStoppedOneToTheFullSpeedOneBySpeed() {
        input.setParameters(400, 100, 20, 10, 60);
        moving(200, 0);
        input.setRatios(100, 100, 100);
        // (20 - 60) * 200/400 + 60 = 40
        assertEquals(40, ActionFixture.fire(input).getRotVel(), 1e-9);
        moving(400, 0);
        assertEquals(20, ActionFixture.fire(input).getRotVel(), 1e-9);
        input.setRatios(-100, 100, 100);
        // backwards: (10 - 60) * 400/400 + 60 = 10
        assertEquals(10, ActionFixture.fire(input).getRotVel(), 1e-9);
    }

    @Test
    void theRatiosArePulledIntoTheirRanges() {
        input.setRatios(150, -130, 120);
        assertEquals(100, input.getTransRatio());
        assertEquals(-100, input.getRotRatio());
        assertEquals(100, input.getThrottleRatio());
        input.setThrottleRatio(-5);
        assertEquals(0, input.getThrottleRatio());
    }

    @Test
    void reversingTheMotionAsksWeaklyForThreeTimesTheDeceleration() {
        moving(300, 20);
        input.setRatios(-60, -60, 100);
        ArActionDesired d = ActionFixture.fire(input);
        assertEquals(robot.getTransDecel() * 3, d.getTransDecel(), 1e-9);
        assertEquals(ArActionDesired.MIN_STRENGTH, d.getTransDecelStrength(), 1e-12);
        assertEquals(robot.getRotDecel() * 3, d.getRotDecel(), 1e-9);
        input.setRatios(-40, 0, 100);
        assertEquals(0, ActionFixture.fire(input).getTransDecelStrength(), "not beyond 50 the other way");
    }

    @Test
    void fireCallbacksRunLowestPriorityFirstSoTheHighestWins() {
        List<String> order = new ArrayList<>();
        input.addFireCallback(30, () -> {
            order.add("30");
            input.setRatios(80, 0, 100);
        });
        input.addFireCallback(10, () -> {
            order.add("10");
            input.setRatios(20, 0, 100);
        });
        assertEquals(transMax * 0.8, ActionFixture.fire(input).getVel(), 1e-9);
        assertEquals(List.of("10", "30"), order);
    }

    @Test
    void activatingAnInactiveInputZeroesTheRatiosAndCallsTheCallbacks() {
        List<String> calls = new ArrayList<>();
        input.addActivateCallback(() -> calls.add("last"));
        input.addActivateCallback(() -> calls.add("first"), ArListPos.FIRST);
        input.setRatios(50, 50, 50);
        input.activate();
        assertEquals(List.of(), calls, "already active: nothing");
        assertEquals(50, input.getTransRatio());
        input.deactivate();
        input.activate();
        assertEquals(List.of("first", "last"), calls);
        assertEquals(0, input.getTransRatio());
        assertEquals(0, input.getThrottleRatio());
    }

    @Test
    void deactivatingAnActiveInputKeepsItsRatiosAsARIAsCodeDoes() {
        List<String> calls = new ArrayList<>();
        input.addDeactivateCallback(() -> calls.add("d"));
        input.setRatios(50, 50, 50);
        input.deactivate();
        assertFalse(input.isActive());
        assertEquals(50, input.getTransRatio());
        assertEquals(List.of(), calls);
        input.deactivate();
        assertEquals(0, input.getTransRatio());
        assertEquals(List.of("d"), calls);
    }
}
