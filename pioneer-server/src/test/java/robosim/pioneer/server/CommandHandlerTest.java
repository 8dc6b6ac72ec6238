package robosim.pioneer.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.pioneer.Commands;
import robosim.pioneer.PioneerPacket;
import robosim.protocol.Command;
import robosim.protocol.RobotParameters;

class CommandHandlerTest {
    private final List<Command> requests = new ArrayList<>();
    private final List<String> log = new ArrayList<>();
    private final List<String> effects = new ArrayList<>();
    private final OdometryFrame frame = new OdometryFrame();
    private final RobotParameters params = new RobotParameters("Pioneer", "p3dx", 250, 425, 210, 301, 2200, 500, 300,
            300, 100, 100, 0.0056, 5000, List.of());
    private final CommandHandler handler = new CommandHandler("r1", params, SipBuilderTest.P3DX, new LaserScan(), frame,
            new CommandHandler.Effects() {
                @Override
                public void request(Command c) {
                    requests.add(c);
                }

                @Override
                public void reply(PioneerPacket p) {
                    effects.add("reply " + p.id());
                }

                @Override
                public void resetOdometry() {
                    effects.add("SETO");
                }

                @Override
                public void resetToStart() {
                    effects.add("SIM_RESET");
                }

                @Override
                public void simStat(int mode) {
                    effects.add("SIM_STAT " + mode);
                }

                @Override
                public void close(String reason) {
                    effects.add("close");
                }

                @Override
                public void simExit(int code) {
                    effects.add("SIM_EXIT " + code);
                }

                @Override
                public void log(String kind, java.util.function.Supplier<String> line) {
                    log.add(line.get());
                }
            });

    @Test
    void enableSwitchesTheRobotsMotorsAndMotionGoesToTheEnvironmentWhichDecides() {
        handler.handle(Commands.comInt(Commands.VEL, 300));
        handler.handle(Commands.comInt(Commands.ENABLE, 1));
        handler.handle(Commands.comInt(Commands.VEL, -300));
        handler.handle(Commands.comInt(Commands.ENABLE, 0));
        assertEquals(List.of(new Command.SetVel(300), new Command.SetMotors(true), new Command.SetVel(-300),
                new Command.SetMotors(false)), requests);
        assertEquals(List.of(), log);
    }

    @Test
    void vel2IsInUnitsOfTheVel2Divisor() {
        handler.handle(Commands.com2Bytes(Commands.VEL2, -5, 10));
        assertEquals(List.of(new Command.SetVel2(-100, 200)), requests);
    }

    @Test
    void headIsInTheRobotsOwnFrame() {
        frame.resetAt(0, 0, 30);
        handler.handle(Commands.comInt(Commands.HEAD, 90));
        assertEquals(List.of(new Command.SetHeading(120)), requests);
    }

    @Test
    void setaWithANegativeValueSetsTheDecelerationAndZeroKeepsTheLimit() {
        handler.handle(Commands.comInt(Commands.SETA, -500));
        handler.handle(Commands.comInt(Commands.SETRA, 0));
        handler.handle(Commands.comInt(Commands.SETRA, 80));
        assertEquals(List.of(new Command.SetDriveLimit(Command.DriveLimit.TRANS_DECEL, 500),
                new Command.SetDriveLimit(Command.DriveLimit.ROT_ACCEL, 80)), requests);
        assertEquals(500, handler.config("r1", 100, 2000).transDecel());
        assertEquals(80, handler.config("r1", 100, 2000).rotAccel());
    }

    @Test
    void anUnknownCommandIsLoggedOnce() {
        handler.handle(Commands.com(199));
        handler.handle(Commands.com(199));
        assertEquals(1, log.size());
        assertEquals("robot r1: unknown command 199; ignored (said once)", log.get(0));
    }

    @Test
    void aCommandWithoutItsArgumentIsDroppedWithALogLine() {
        handler.handle(Commands.com(Commands.VEL));
        assertTrue(log.get(0).startsWith("robot r1: dropped a malformed command: packet 11 (VEL)"), log.get(0));
    }

    @Test
    void simulatorCommandsBecomeRequestsOrEffects() {
        handler.handle(Commands.simSetPose(1000, -2000, 90));
        handler.handle(Commands.com(Commands.SIM_RESET));
        handler.handle(Commands.comInt(Commands.SIM_STAT, 2));
        handler.handle(Commands.comInt(Commands.SIM_EXIT, 4));
        handler.handle(Commands.comStr(Commands.SIM_MESSAGE, "hello"));
        handler.handle(Commands.com(Commands.SETO));
        assertEquals(List.of(new Command.SetTruePose(1000, -2000, 90), new Command.Say("hello")), requests);
        assertEquals(List.of("SIM_RESET", "SIM_STAT 2", "SIM_EXIT 4", "SETO"), effects);
    }

    @Test
    void theConfigReplyCarriesSimAndTheParameterFilesLimits() {
        var c = handler.config("r1", 100, 2000);
        assertEquals("SIM", c.serial());
        assertEquals(2200, c.transVelMax());
        assertEquals(500, c.rotVelMax());
        handler.handle(Commands.comInt(Commands.SETV, 400));
        assertEquals(400, handler.config("r1", 100, 2000).transVelMax());
    }
}
