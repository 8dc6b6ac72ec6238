package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;
import robosim.protocol.GripperState;

/**
 * ArGripper on a connected robot: each call sends ARIA's GRIPPER code (ArGripper.h's
 * {@code ArGripperCommands}) and answers that it was sent; a value out of range is refused before
 * anything is sent; the getters read the robot's latest gripper state.
 */
class ArGripperCommandsTest {
    private final ConnectedRobot robot = new ConnectedRobot("p3dx-gripper");
    private final ArGripper gripper = new ArGripper(robot, ArGripper.Type.GENIO);

    private void sends(int op, BooleanSupplier call) {
        assertTrue(call.getAsBoolean(), "sent");
        assertEquals(new Command.Gripper(op, 0), robot.last());
    }

    @Test
    void eachOperationSendsItsCode() {
        sends(Command.Gripper.GRIP_STOP, gripper::gripStop);
        sends(Command.Gripper.LIFT_UP, gripper::liftUp);
        sends(Command.Gripper.LIFT_DOWN, gripper::liftDown);
        sends(Command.Gripper.LIFT_STOP, gripper::liftStop);
        sends(Command.Gripper.GRIPPER_STORE, gripper::gripperStore);
        sends(Command.Gripper.GRIPPER_HALT, gripper::gripperHalt);
        sends(Command.Gripper.GRIP_OPEN, gripper::gripOpen);
        sends(Command.Gripper.GRIP_CLOSE, gripper::gripClose);
        sends(Command.Gripper.GRIPPER_DEPLOY, gripper::gripperDeploy);
        assertEquals(9, robot.sent.size(), "one command a call");
    }

    @Test
    void theGraspTimeIsSentWithinAriasByteAndRefusedBeyondIt() {
        assertTrue(gripper.gripPressure(255));
        assertEquals(new Command.Gripper(Command.Gripper.GRIP_PRESSURE, 255), robot.last());
        assertTrue(gripper.gripPressure(0));
        assertFalse(gripper.gripPressure(256), "beyond 255 twenty-ms units");
        assertFalse(gripper.gripPressure(-1));
        assertEquals(2, robot.sent.size(), "nothing sent for a refused value");
    }

    @Test
    void theLiftCarryIsASigned16BitTime() {
        assertTrue(gripper.liftCarry(-32768));
        assertEquals(new Command.Gripper(Command.Gripper.LIFT_CARRY, -32768), robot.last());
        assertFalse(gripper.liftCarry(32768));
        assertEquals(1, robot.sent.size());
    }

    @Test
    void theGraspTimeIsReadFromTheLatestStateAndIsZeroWithoutOne() {
        assertEquals(0, gripper.getGraspTime(), "before any state");
        robot.cycle(new GripperState(GripperState.PADDLES_OPEN_CLEAR, 12, 0, 0, 0), null, null);
        assertEquals(12, gripper.getGraspTime());
        assertEquals(0, new ArGripper(robot, ArGripper.Type.NOGRIPPER).getGraspTime(), "no gripper: nothing to read");
    }

    @Test
    void aQueriedTypeIsAnsweredByTheFirstStateOfAConnectedRobot() {
        ArGripper queried = new ArGripper(robot);
        assertEquals(ArGripper.Type.QUERYTYPE, queried.getType(), "no state yet");
        robot.cycle(new GripperState(0, 0, 0, 0, 0), null, null);
        assertEquals(ArGripper.Type.GENIO, queried.getType());

        ConnectedRobot without = new ConnectedRobot("p3dx");
        ArGripper none = new ArGripper(without);
        without.cycle(null, null, null);
        assertEquals(ArGripper.Type.NOGRIPPER, none.getType());
        assertEquals("There is no gripper.", none.stateLine());
        assertEquals(List.of(), without.sent);
    }
}
