package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;

/**
 * The robot's action handler and state reflector (ArRobot.cpp): what the resolved desire sends, and
 * how direct motion commands and actions take turns.
 */
class ActionDriverTest {
    private static ArAction wanting(String name, Consumer<ArActionDesired> wish) {
        return new ArAction(name) {
            @Override
            public ArActionDesired fire(ArActionDesired currentDesired) {
                ArActionDesired d = new ArActionDesired();
                wish.accept(d);
                return d;
            }
        };
    }

    private final RecordingRobot robot = new RecordingRobot();
    private long time;

    private List<Command> cycle() {
        time += 100;
        Cycles.cycle(robot, time, 0, 0, 0);
        return robot.take();
    }

    @Test
    void anActionsVelocityIsSentOnceAndAgainOnlyWhenItChangesOrEveryHalfSecond() {
        double[] vel = {300};
        robot.addAction(wanting("go", d -> d.setVel(vel[0])), 50);

        assertEquals(List.of(new Command.SetVel(300)), cycle());
        assertEquals(List.of(), cycle());
        vel[0] = 200;
        assertEquals(List.of(new Command.SetVel(200)), cycle());
        for (int i = 0; i < 4; i++) {
            assertEquals(List.of(), cycle());
        }
        // 500 ms after it was sent, ARIA's state reflection sends it again
        assertEquals(List.of(new Command.SetVel(200)), cycle());
    }

    @Test
    void theVelocityIsHeldWithinTheActionsMaximum() {
        robot.addAction(wanting("limit", d -> d.setMaxVel(150)), 90);
        robot.addAction(wanting("go", d -> d.setVel(400)), 10);

        assertEquals(List.of(new Command.SetVel(150)), cycle());
    }

    @Test
    void aDeltaHeadingIsSentAsAnAbsoluteHeadingAndZeroStopsTheRotation() {
        double[] delta = {45};
        robot.addAction(wanting("turn", d -> d.setDeltaHeading(delta[0])), 50);

        assertEquals(List.of(new Command.SetHeading(45)), cycle());
        delta[0] = 0;
        assertEquals(List.of(new Command.SetRotVel(0)), cycle());
    }

    @Test
    void anActionsAccelerationIsSentAndTheRobotsOwnComesBackAfter() {
        boolean[] wants = {true};
        robot.addAction(wanting("gentle", d -> {
            if (wants[0]) {
                d.setTransAccel(100);
            }
        }), 50);

        assertEquals(List.of(new Command.SetDriveLimit(Command.DriveLimit.TRANS_ACCEL, 100)), cycle());
        assertEquals(List.of(), cycle());
        wants[0] = false;
        assertEquals(List.of(new Command.SetDriveLimit(Command.DriveLimit.TRANS_ACCEL, robot.getTransAccel())),
                cycle());
    }

    @Test
    void aDirectCommandTakesItsChannelUntilClearDirectMotion() {
        robot.addAction(wanting("go", d -> {
            d.setVel(300);
            d.setRotVel(10);
        }), 50);
        cycle();

        robot.setVel(100);
        assertEquals(List.of(new Command.SetVel(100)), robot.take());
        // translation is the program's now; rotation stays the actions'
        assertEquals(List.of(), cycle());
        assertTrue(robot.isDirectMotion());

        robot.clearDirectMotion();
        assertFalse(robot.isDirectMotion());
        // the actions' last values are forgotten, so both channels are sent again
        assertEquals(List.of(new Command.SetVel(300), new Command.SetRotVel(10)), cycle());
    }

    @Test
    void stopHoldsBothChannelsAsInAria() {
        robot.addAction(wanting("go", d -> {
            d.setVel(300);
            d.setRotVel(10);
        }), 50);
        cycle();

        robot.stop();
        robot.take();

        assertEquals(List.of(), cycle());
        assertEquals(List.of(), cycle());
    }

    @Test
    void withAPrecedenceTimeTheActionsTakeOverAgainWhenItRunsOut() {
        robot.setDirectMotionPrecedenceTime(300);
        robot.addAction(wanting("go", d -> d.setVel(300)), 50);
        cycle();
        robot.setVel(0);
        robot.take();

        assertEquals(List.of(), cycle());
        assertEquals(List.of(), cycle());
        assertTrue(robot.isDirectMotion());
        // 300 ms after the direct command the actions have translation again; as in ARIA, their
        // unchanged velocity goes out at the next state reflection refresh, 500 ms after the last
        assertEquals(List.of(), cycle());
        assertFalse(robot.isDirectMotion());
        assertEquals(List.of(), cycle());
        assertEquals(List.of(new Command.SetVel(300)), cycle());
    }

    @Test
    void actionsAreFoundRemovedAndSwitchedTogetherInGroups() {
        ArAction a = wanting("a", d -> d.setVel(100));
        ArAction b = wanting("b", d -> d.setVel(200));
        ArActionGroup group = new ArActionGroup(robot);
        robot.addAction(a, 50);
        group.addAction(b, 60);

        assertSame(a, robot.findAction("a"));
        assertSame(robot, b.getRobot());
        assertEquals(List.of("b", "a"), robot.getActionList().stream().map(e -> e.action().getName()).toList());

        group.activateExclusive();
        assertFalse(a.isActive());
        assertTrue(b.isActive());
        assertEquals(List.of(new Command.SetVel(200)), cycle());

        assertTrue(robot.remAction("b"));
        assertNull(robot.findAction("b"));
        assertFalse(robot.remAction(b));
    }

    @Test
    void equalPrioritiesFireTheLastAddedFirst() {
        List<String> fired = new ArrayList<>();
        robot.addAction(wanting("first", d -> fired.add("first")), 50);
        robot.addAction(wanting("second", d -> fired.add("second")), 50);
        robot.addAction(wanting("high", d -> fired.add("high")), 70);

        cycle();

        assertEquals(List.of("high", "second", "first"), fired);
    }

    @Test
    void actionsFireAfterTheSensorTasksAndBeforeTheUserTasks() {
        List<String> order = new ArrayList<>();
        robot.addSensorInterpTask("sensor", 50, () -> order.add("sensor"));
        robot.addUserTask("user", 50, () -> order.add("user"));
        robot.addAction(wanting("action", d -> order.add("action")), 50);

        cycle();

        assertEquals(List.of("sensor", "action", "user"), order);
    }
}
