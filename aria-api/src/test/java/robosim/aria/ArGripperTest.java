package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import org.junit.jupiter.api.Test;

/** ArGripper before a robot is connected, as ARIA's answers for an unknown or absent gripper. */
class ArGripperTest {
    private final ArRobot robot = new ArRobot("r1", "127.0.0.1", 1, "p3dx-gripper");

    @Test
    void commandsToARobotNotConnectedAreNotSent() {
        ArGripper g = new ArGripper(robot);
        assertFalse(g.gripOpen());
        assertFalse(g.gripClose());
        assertFalse(g.liftCarry(10));
        assertFalse(g.gripperDeploy());
    }

    @Test
    void theTypeStaysQueriedUntilTheRobotAnswersAndTheGettersAnswerNothing() {
        ArGripper g = new ArGripper(robot);
        assertEquals(ArGripper.Type.QUERYTYPE, g.getType());
        assertEquals(0, g.getGripState());
        assertEquals(0, g.getPaddleState());
        assertEquals(0, g.getBreakBeamState());
        assertFalse(g.isLiftMaxed());
        assertFalse(g.isGripMoving());
        assertFalse(g.isLiftMoving());
        assertEquals("Querying gripper type.", g.stateLine());
    }

    @Test
    void aGripperSetToNoneSaysSo() {
        ArGripper g = new ArGripper(robot, ArGripper.Type.NOGRIPPER);
        assertEquals("There is no gripper.", g.logState());
        g.setType(null);
        assertEquals(ArGripper.Type.QUERYTYPE, g.getType());
    }
}
