package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.Command;

/** An ARIA program's direct commands (comInt and the like) carried out by the calls that do the same. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class ArCommandsTest {
    @Test
    void motionCommandsAreTheCallsThatDoTheSame() {
        RecordingRobot robot = new RecordingRobot();
        assertTrue(robot.comInt(ArCommands.VEL, 300));
        assertTrue(robot.comInt(ArCommands.RVEL, -20));
        assertTrue(robot.comInt(ArCommands.MOVE, 1000));
        assertTrue(robot.comInt(ArCommands.HEAD, 90));
        assertTrue(robot.comInt(ArCommands.DHEAD, -45));
        assertTrue(robot.com(ArCommands.STOP));
        // VEL2: left 10 (200 mm/s) in the high byte, right -5 (-100 mm/s) in the low
        assertTrue(robot.com2Bytes(ArCommands.VEL2, 10, -5));
        assertEquals(List.of(new Command.SetVel(300), new Command.SetRotVel(-20), new Command.Move(1000),
                new Command.SetHeading(90), new Command.SetDeltaHeading(-45), new Command.Stop(),
                new Command.SetVel2(200, -100)), robot.sent);
    }

    @Test
    void soundIsTakenAndOtherCommandsAreRefusedWithALogLine() {
        ByteArrayOutputStream log = new ByteArrayOutputStream();
        ArLog.setStream(new PrintStream(log, true, StandardCharsets.UTF_8));
        try {
            RecordingRobot robot = new RecordingRobot();
            assertTrue(robot.comInt(ArCommands.SOUNDTOG, 0));
            assertTrue(robot.comStr(ArCommands.SAY, "beep"));
            assertTrue(robot.sent.isEmpty());
            assertFalse(robot.comInt(ArCommands.JOYDRIVE, 1));
            assertFalse(robot.comStr(ArCommands.TTY2, "x"));
            assertEquals("ArRobot::comInt: command 47 is not simulated; ignored\n"
                    + "ArRobot::comStr: command 42 is not simulated; ignored\n", log.toString(StandardCharsets.UTF_8));
        } finally {
            ArLog.setStream(null);
        }
    }
}
