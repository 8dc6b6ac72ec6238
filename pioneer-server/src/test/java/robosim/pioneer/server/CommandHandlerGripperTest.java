package robosim.pioneer.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.pioneer.Commands;
import robosim.pioneer.GripperPacket;
import robosim.protocol.Command;
import robosim.protocol.GripperState;
import robosim.protocol.RobotParameters;
import robosim.protocol.RobotState;

/**
 * The gripper's commands on the Pioneer port, and the numbers they share with the older simulator's
 * laser commands (36 GRIPPERVAL / laser start, 37 GRIPPERPACREQUEST / laser end).
 */
class CommandHandlerGripperTest {
    private static final RobotParameters PLAIN = new RobotParameters("Pioneer", "p3dx", 250, 425, 210, 301, 2200, 500,
            300, 300, 100, 100, 0.0056, 5000, List.of());

    private final List<Command> requests = new ArrayList<>();
    private final List<String> log = new ArrayList<>();
    private final LaserScan laser = new LaserScan();

    private CommandHandler handler(RobotParameters params) {
        return new CommandHandler("r1", params, SipBuilderTest.P3DX, laser, new OdometryFrame(),
                new RecordingEffects(requests, log));
    }

    private static RobotState withGripper(int switches) {
        return new RobotState(3, 300, 0, 0, 0, 0, 0, 0, 0, false, 0)
                .with(GripperState.PART, new GripperState(switches, 10, 0, 0, -1));
    }

    @Test
    void gripperCodesBecomeTheEnvironmentsGripperRequests() {
        CommandHandler h = handler(PLAIN.withGripper(true));
        h.handle(Commands.comInt(Commands.GRIPPER, Command.Gripper.GRIP_OPEN));
        h.handle(Commands.comInt(Commands.GRIPPER, Command.Gripper.LIFT_UP));
        h.handle(Commands.comInt(Commands.GRIPPER, Command.Gripper.GRIPPER_HALT));
        assertEquals(List.of(new Command.Gripper(1), new Command.Gripper(4), new Command.Gripper(15)), requests);
        assertEquals(List.of(), log);
    }

    @Test
    void gripperValAfterGripPressureOrLiftCarryIsItsArgumentNotTheLasersStart() {
        CommandHandler h = handler(PLAIN.withGripper(true));
        h.handle(Commands.comInt(Commands.GRIPPER, Command.Gripper.GRIP_PRESSURE));
        h.handle(Commands.comInt(Commands.PULSE, 0));
        h.handle(Commands.comInt(Commands.GRIPPERVAL, 50));
        h.handle(Commands.comInt(Commands.GRIPPER, Command.Gripper.LIFT_CARRY));
        h.handle(Commands.comInt(Commands.GRIPPERVAL, -20));
        assertEquals(List.of(new Command.Gripper(16, 50), new Command.Gripper(17, -20)), requests);
        // then 36 alone is the laser's first angle again
        h.handle(Commands.comInt(36, -45));
        h.handle(Commands.comInt(35, 1));
        assertEquals(136, laser.packets(new int[181]).get(0).total(), "-45° to 90° at 1°");
    }

    @Test
    void ariasSimulatedLaserStillConfiguresWithTheOldCommandsOnAGripperRobot() {
        CommandHandler h = handler(PLAIN.withGripper(true));
        // ArSimulatedLaser::internalConnect: 36 start, 37 end, 38 increment, 35 enable
        h.handle(Commands.comInt(36, -45));
        h.handle(Commands.comInt(37, 45));
        h.handle(Commands.comInt(38, 100));
        h.handle(Commands.comInt(35, 2));
        assertEquals(91, laser.packets(new int[181]).get(0).total(), "-45° to 45° at 1°");
        assertNull(h.gripperReports().next(withGripper(0x31)), "37 with 45 asked for no gripper packet");
    }

    @Test
    void gripperPacRequestTwoSendsOnePacketEveryCycleUntilZero() {
        CommandHandler h = handler(PLAIN.withGripper(true));
        h.handle(Commands.comInt(Commands.GRIPPERPACREQUEST, 2));
        assertNull(h.gripperReports().next(new RobotState(0, 0, 0, 0, 0, 0, 0, 0, 0, false, 0)),
                "not before a state carries the gripper");
        assertEquals(new GripperPacket(GripperPacket.GENERAL_IO, 0x31, 10), h.gripperReports().next(withGripper(0x31)));
        assertEquals(new GripperPacket(GripperPacket.GENERAL_IO, 0x02, 10), h.gripperReports().next(withGripper(0x02)));
        h.handle(Commands.comInt(Commands.GRIPPERPACREQUEST, 0));
        assertNull(h.gripperReports().next(withGripper(0x31)));
        h.handle(Commands.comInt(Commands.GRIPPERPACREQUEST, 1));
        assertEquals(0x31, h.gripperReports().next(withGripper(0x31)).switches());
        assertNull(h.gripperReports().next(withGripper(0x31)), "1: one packet");
        assertEquals(List.of(), requests, "the laser was not touched");
    }

    @Test
    void aRobotWithoutAGripperAnswersTheQueryWithTypeZeroAndIgnoresGripperWithOneLogLine() {
        CommandHandler h = handler(PLAIN);
        h.handle(Commands.comInt(Commands.GRIPPERPACREQUEST, 2));
        assertEquals(new GripperPacket(GripperPacket.NONE, 0, 0),
                h.gripperReports().next(new RobotState(1, 100, 0, 0, 0, 0, 0, 0, 0, false, 0)));
        h.handle(Commands.comInt(Commands.GRIPPER, Command.Gripper.GRIP_CLOSE));
        h.handle(Commands.comInt(Commands.GRIPPER, Command.Gripper.GRIP_OPEN));
        assertEquals(List.of(), requests);
        assertEquals(1, log.size(), log.toString());
        assertTrue(log.get(0).contains("has no gripper"), log.toString());
    }

    @Test
    void theConfigReplySaysWhetherTheRobotHasAGripper() {
        assertTrue(handler(PLAIN.withGripper(true)).config("r1", 100, 2000).hasGripper());
        assertEquals(false, handler(PLAIN).config("r1", 100, 2000).hasGripper());
    }

    @Test
    void gripperOperationsOfOneStepAreKeptOnePerCodeSoLiftUpDoesNotUndoOpen() {
        PendingCommands pending = new PendingCommands();
        pending.add(new Command.Gripper(Command.Gripper.GRIP_OPEN));
        pending.add(new Command.Gripper(Command.Gripper.LIFT_UP));
        pending.add(new Command.Gripper(Command.Gripper.GRIP_OPEN));
        assertEquals(List.of(new Command.Gripper(4), new Command.Gripper(1)), pending.drain());
    }

    @Test
    void theSipsAnportHighByteIsTheSwitchesAndTheDeployedGripperBeforeTheStateCarriesIt() {
        OdometryFrame frame = new OdometryFrame();
        SipBuilder sips = new SipBuilder(SipBuilderTest.P3DX, true);
        byte[] data = sips.build(withGripper(0x31), frame, true, false).toPacket().data();
        // no sonar readings: ANPORT follows the 18 bytes of motion and flags and the count, low byte first
        assertEquals(0x00, data[19] & 0xff);
        assertEquals(0x31, data[20] & 0xff);
        RobotState bare = new RobotState(0, 0, 0, 0, 0, 0, 0, 0, 0, false, 0);
        assertEquals(0x3000, sips.standing(bare, frame, false, false).anPort(),
                "before the welcome: paddles open, lift down, nothing triggered");
        assertEquals(0, new SipBuilder(SipBuilderTest.P3DX, false).build(bare, frame, true, false).anPort(),
                "no gripper: ANPORT 0");
    }
}
