package robosim.remote.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.aria.ArActionKeydrive;
import robosim.aria.ArRobot;
import robosim.hw.RobotSensorResponse;
import robosim.params.RobotParameterFiles;
import robosim.protocol.Command;
import robosim.protocol.RobotState;
import robosim.remote.KeyDrive;

/** With keydrive on, the arrow keys feed ARIA's ArActionKeydrive on the robot, cycle by cycle, without a network. */
class PioneerRemoteKeydriveTest {
    /** A p3dx that keeps what it would send; the test runs its cycles. */
    private static final class Recording extends ArRobot {
        final List<Command> sent = new ArrayList<>();
        private long time;

        Recording() {
            super("r1", "127.0.0.1", 5000, RobotParameterFiles.load("p3dx"));
        }

        @Override
        protected void request(Command command) {
            sent.add(command);
        }

        List<Command> cycle() {
            sent.clear();
            time += 100;
            responded(new RobotSensorResponse(new RobotState(getCounter() + 1, time, 0, 0, 0, 0, 0, 0, 0, false,
                    0)));
            return List.copyOf(sent);
        }
    }

    private final Recording robot = new Recording();

    @Test
    void theKeydriveActionIsAddedAndEachPressStepsItsSpeed() {
        PioneerRemote remote = new PioneerRemote(robot, true);
        assertTrue(remote.keydrive());
        assertTrue(robot.findAction("keydrive") instanceof ArActionKeydrive);
        remote.keydrive(KeyDrive.Key.FORWARD);
        remote.keydrive(KeyDrive.Key.FORWARD);
        remote.keydrive(KeyDrive.Key.LEFT);
        List<Command> sent = robot.cycle();
        assertTrue(sent.contains(new Command.SetVel(50)), sent.toString());
        assertTrue(sent.contains(new Command.SetHeading(8)), sent.toString());
    }

    @Test
    void aStopTakesOverAndTheNextPressStartsFromStandingStill() {
        PioneerRemote remote = new PioneerRemote(robot, true);
        for (int i = 0; i < 4; i++) {
            remote.keydrive(KeyDrive.Key.FORWARD);
        }
        assertTrue(robot.cycle().contains(new Command.SetVel(100)));
        remote.stop();
        assertEquals(List.of(new Command.Stop()), List.copyOf(robot.sent).subList(robot.sent.size() - 1, robot.sent.size()));
        assertTrue(robot.isDirectMotion(), "the stop holds the robot");
        remote.keydrive(KeyDrive.Key.FORWARD);
        assertFalse(robot.isDirectMotion(), "a key press gives the robot back to the action");
        List<Command> sent = robot.cycle();
        assertTrue(sent.contains(new Command.SetVel(25)), "from 0, one step: " + sent);
    }

    @Test
    void withoutKeydriveThereIsNoActionAndNoKeydrive() {
        PioneerRemote remote = new PioneerRemote(robot, false);
        assertFalse(remote.keydrive());
        assertEquals(null, robot.findAction("keydrive"));
        assertThrows(UnsupportedOperationException.class, () -> remote.keydrive(KeyDrive.Key.FORWARD));
    }
}
