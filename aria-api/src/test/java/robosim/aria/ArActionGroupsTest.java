package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * ArActionGroups.cpp: what each predefined group holds, at which priorities; that each is used
 * exclusively; and what the guarded ones let through.
 */
@Timeout(20)
class ArActionGroupsTest {
    private final ActionFixture f = new ActionFixture();
    private final ArRangeDevice device = new ArRangeDevice("test", 5000);

    @AfterEach
    void noKeyHandler() {
        Aria.setKeyHandler(null);
    }

    /** The robot's actions as "priority name", highest first. */
    private List<String> actions() {
        List<String> out = new ArrayList<>();
        for (ArResolver.Entry e : f.robot.getActionList()) {
            out.add(e.priority() + " " + e.action().getName());
        }
        return out;
    }

    /** What the robot's active actions want, combined. */
    private ArActionDesired resolve() {
        return new ArPriorityResolver().resolve(f.robot.getActionList(), f.robot, false).copy();
    }

    /** The velocity the combined desire comes to: its velocity held within its maximum. */
    private static double velocity(ArActionDesired d) {
        double v = d.getVel();
        if (d.getMaxVelStrength() > 0) {
            v = Math.min(v, d.getMaxVel());
        }
        return v;
    }

    @Test
    void eachGroupHoldsARIAsActionsAtARIAsPriorities() {
        new ArActionGroupTeleop(f.robot);
        assertEquals(List.of("100 TableSensorLimiter", "90 Speed Limiter Near", "89 Speed Limiter Far",
                "80 speed limiter", "70 joydrive", "69 keydrive"), actions());
        ActionFixture g = new ActionFixture();
        new ArActionGroupWander(g.robot);
        List<String> wander = new ArrayList<>();
        g.robot.getActionList().forEach(e -> wander.add(e.priority() + " " + e.action().getName()));
        assertEquals(List.of("100 bumpers", "90 stall recover", "79 Avoid Front", "50 Constant Velocity"), wander);
    }

    @Test
    void theOtherGroupsHoldTheirs() {
        new ArActionGroupInput(f.robot);
        assertEquals(List.of("100 TableSensorLimiter", "90 Speed Limiter Near", "89 Speed Limiter Far",
                "80 speed limiter", "70 Input"), actions());
        ActionFixture g = new ActionFixture();
        new ArActionGroupUnguardedTeleop(g.robot);
        new ArActionGroupStop(g.robot);
        new ArActionGroupRatioDrive(g.robot);
        List<String> names = new ArrayList<>();
        g.robot.getActionList().forEach(e -> names.add(e.priority() + " " + e.action().getName()));
        assertEquals(List.of("100 stop", "70 joydrive", "69 keydrive", "50 RatioInput",
                "40 DeceleratingLimiterForward", "39 DeceleratingLimiterBackward"), names);
    }

    @Test
    void activatingAGroupExclusivelySwitchesTheOthersOff() {
        ArActionGroupWander wander = new ArActionGroupWander(f.robot);
        ArActionGroupStop stop = new ArActionGroupStop(f.robot);
        stop.activateExclusive();
        assertTrue(stop.getActionStop().isActive());
        assertTrue(wander.getActionList().stream().noneMatch(ArAction::isActive));
        f.at(0, 0, 0, 0);
        ArActionDesired d = resolve();
        assertEquals(0, d.getVel());
        wander.activateExclusive();
        assertFalse(stop.getActionStop().isActive());
        assertTrue(wander.getActionList().stream().allMatch(ArAction::isActive));
        f.robot.addRangeDevice(device);
        f.at(0, 0, 0, 0);
        assertEquals(400, resolve().getVel(), "nothing near: the wander's constant velocity");
    }

    @Test
    void theWandersParametersReachItsActions() {
        f.robot.addRangeDevice(device);
        new ArActionGroupWander(f.robot, 250, 600, 100, 20);
        f.at(0, 0, 0, 0);
        assertEquals(250, resolve().getVel());
        device.addReading(f.robot.getRobotRadius() + 300, 50);
        ArActionDesired d = resolve();
        assertEquals(-20, d.getDeltaHeading(), "an obstacle ahead-left within 600 mm: turn right by 20");
        assertTrue(d.getVel() < 250, "slowed: " + d.getVel());
    }

    @Test
    void teleopsLimitersHoldTheKeydrivesSpeed() {
        f.robot.addRangeDevice(device);
        ArActionGroupTeleop teleop = new ArActionGroupTeleop(f.robot);
        ArActionKeydrive keys = teleop.getActionKeydrive();
        f.at(0, 0, 0, 0);
        for (int i = 0; i < 16; i++) {
            keys.up();
        }
        assertEquals(400, velocity(resolve()), "nothing near: the keydrive's speed");
        ArActionLimiterForwards near = (ArActionLimiterForwards) f.robot.findAction("Speed Limiter Near");
        ArActionLimiterForwards far = (ArActionLimiterForwards) f.robot.findAction("Speed Limiter Far");
        device.addReading(f.robot.getRobotLength() / 2 + 450, 0);
        double nearMax = ActionFixture.fire(near).getMaxVel();
        double farMax = ActionFixture.fire(far).getMaxVel();
        assertTrue(nearMax > 0 && nearMax < 250 && farMax > 0 && farMax < 400, nearMax + ", " + farMax);
        assertEquals(Math.min(nearMax, farMax), velocity(resolve()), 1e-9, "the slower limiter holds it");
        device.addReading(f.robot.getRobotLength() / 2 + 150, 0);
        assertEquals(0, velocity(resolve()), "within the stop distance: stopped");
        assertFalse(teleop.getActionJoydrive().joystickInited());
    }

    @Test
    void theUnguardedTeleopLetsTheKeydriveThrough() {
        f.robot.addRangeDevice(device);
        ArActionGroupUnguardedTeleop teleop = new ArActionGroupUnguardedTeleop(f.robot);
        f.at(0, 0, 0, 0);
        device.addReading(f.robot.getRobotLength() / 2 + 150, 0);
        for (int i = 0; i < 4; i++) {
            teleop.getActionKeydrive().up();
        }
        assertEquals(100, velocity(resolve()));
    }

    @Test
    void theInputGroupDrivesAtWhatItIsToldWithinItsLimiters() {
        f.robot.addRangeDevice(device);
        ArActionGroupInput input = new ArActionGroupInput(f.robot);
        f.at(0, 0, 0, 0);
        input.setVel(300);
        input.setRotVel(10);
        ArActionDesired d = resolve();
        assertEquals(300, velocity(d));
        assertEquals(10, d.getRotVel());
        device.addReading(f.robot.getRobotLength() / 2 + 150, 0);
        assertEquals(0, velocity(resolve()));
        input.clear();
        assertEquals(0, resolve().getVelStrength(), "cleared: the input wants nothing");
    }

    @Test
    void theRatioDriveReadsTheArrowKeysThroughItsRatioInput() {
        ArKeyHandler h = ArActionKeydriveKeysTest.keys(ArActionKeydriveKeysTest.UP.repeat(4) + ArActionKeydriveKeysTest.LEFT);
        f.robot.addRangeDevice(device);
        ArActionGroupRatioDrive drive = new ArActionGroupRatioDrive(f.robot);
        drive.activateExclusive();
        f.at(0, 0, 0, 0);
        assertEquals(0, velocity(resolve()), "no key yet");
        assertTrue(drive.getRatioInputKeydrive().haveKeys(), "its first firing took the keys");
        h.checkKeys();
        ArActionDesired d = resolve();
        assertEquals(20, drive.getActionRatioInput().getTransRatio());
        assertEquals(0.2 * f.robot.getTransVelMax(), velocity(d), 1e-9);
        assertTrue(d.getRotVel() > 0, "LEFT: a left turn for one firing");
        assertEquals(0, resolve().getRotVel(), "then no turn");
    }

    @Test
    void theRatioDrivesLimiterStopsItShortOfAnObstacle() {
        f.robot.addRangeDevice(device);
        ArActionGroupRatioDrive drive = new ArActionGroupRatioDrive(f.robot);
        ArActionGroupRatioDriveUnsafe unsafe = new ArActionGroupRatioDriveUnsafe(f.robot);
        f.at(0, 0, 0, 0);
        device.addReading(f.robot.getRobotLength() / 2 + 50, 0);
        drive.activateExclusive();
        drive.getRatioInputKeydrive().up();
        drive.getRatioInputKeydrive().up();
        drive.getRatioInputKeydrive().up();
        assertEquals(0, velocity(resolve()), "guarded: the decelerating limiter holds it");
        unsafe.activateExclusive();
        unsafe.getRatioInputKeydrive().up();
        unsafe.getRatioInputKeydrive().up();
        assertEquals(0, velocity(resolve()), "two presses: a ratio of 10, inside the dead zone");
        unsafe.getRatioInputKeydrive().up();
        assertEquals(0.15 * f.robot.getTransVelMax(), velocity(resolve()), 1e-9, "unsafe: nothing holds it");
    }
}
