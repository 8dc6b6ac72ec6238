package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.pioneer.Commands;
import robosim.pioneer.PioneerClient;
import robosim.pioneer.Sip;
import robosim.protocol.RobotState;
import robosim.protocol.SonarReading;

/**
 * An ARIA program's connection to a Pioneer port does not wait on the run: the handshake is answered
 * at once, and while the run waits for the world's other robots the client is sent its robot
 * standing at its start pose, as ARIA needs to stay connected. Checked with ARIA's own patience
 * ({@link AriaHandshakeClient}), also on a machine kept busy on purpose.
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class PioneerHandshakeAtOnceTest {
    /** p3dx's DistConvFactor. */
    static final double DIST = 0.485;

    @TempDir
    Path dir;

    @Test
    void aClientOfOneRobotOfTwoSeesItStandAtItsStartPoseUntilTheRunStartsThenItsCommandsTakeEffect() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.roomForTwo(dir), false, code -> { });
             AriaHandshakeClient c = AriaHandshakeClient.connect("127.0.0.1", run.ports.portOf("r1"))) {
            assertEquals("SIM", c.handshake().config().serial());
            assertEquals("r1", c.handshake().identity().name());
            c.send(Commands.comInt(Commands.ENABLE, 1));
            c.send(Commands.comInt(Commands.VEL, 200));
            RobotState start = run.env.sim.state("r1");
            for (int i = 0; i < 20; i++) {
                Sip s = c.nextSip();
                assertEquals(0, run.env.sim.stepCount(), "the run waits for r2");
                assertEquals(0, s.xPos());
                assertEquals(0, s.yPos());
                assertEquals(0, s.th());
                assertEquals(0, s.leftVel(), "standing: the commands wait for the run");
                assertEquals(0, s.rightVel());
                for (Sip.SonarReading r : s.sonar()) {
                    assertEquals(start.get(SonarReading.PART).ranges()[r.index()], r.range(), 1, "sonar " + r.index() + " at the start pose");
                }
            }
            try (PioneerClient other = run.client("r2")) {
                Sip s = c.nextSip();
                for (int i = 0; i < 100 && s.leftVel() != 200; i++) {
                    s = c.nextSip();
                }
                assertEquals(200, s.leftVel(), "ENABLE 1 and VEL 200, given before the run, take effect with it");
                assertTrue(run.env.sim.stepCount() > 0, "the run started");
                Sip later = c.nextSip();
                for (int i = 0; i < 100 && later.xPos() * DIST < 100; i++) {
                    later = c.nextSip();
                }
                assertTrue(later.xPos() * DIST >= 100, "r1 drove on: " + later.xPos() * DIST + " mm");
                assertFalse(other.isClosed());
            }
        }
    }

    @Test
    void ariasHandshakeWithAriasPatienceSucceedsOnAMachineKeptBusy() throws Exception {
        try (BusyMachine busy = BusyMachine.twiceTheCores()) {
            for (int round = 0; round < 3; round++) {
                // a new Environment each time: the robot's welcome is under way, on a busy machine, as ARIA connects
                try (PioneerRun run = new PioneerRun(PioneerRun.roomForTwo(dir), false, code -> { });
                     AriaHandshakeClient c = AriaHandshakeClient.connect("127.0.0.1", run.ports.portOf("r1"))) {
                    assertEquals("SIM", c.handshake().config().serial(), "round " + round);
                    for (int i = 0; i < 5; i++) {
                        c.nextSip();
                    }
                }
            }
        }
    }

    @Test
    void envReportsARobotWhoseAriaClientLeftBeforeTheRunAsStandingNotAsRunToTheEnd() throws Exception {
        Path world = dir.resolve("room2.xml");
        String params = LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p").toString();
        Files.writeString(world, """
                <world name="room" width="10000" height="10000" boundary="true">
                  <robot name="r1" type="pioneer" x="3000" y="3000" th="0" params="%s"/>
                  <robot name="r2" type="pioneer" x="3000" y="6000" th="0" params="%s"/>
                </world>
                """.formatted(params, params));
        try (LauncherJvm env = new LauncherJvm("env", world.toString(), "--robot-port", "0", "--viewer-port", "0",
                "--pioneer-port", "0", "--steps", "20", "--quiet")) {
            String line = env.awaitLine(l -> l.startsWith("Pioneer ports on 127.0.0.1: "), 60);
            try (AriaHandshakeClient c = AriaHandshakeClient.connect("127.0.0.1", port(line, "r1"))) {
                c.nextSip();
            } // ENABLE 0 and CLOSE, before r2 has a client: before the run starts
            try (PioneerClient c = PioneerClient.connect("127.0.0.1", port(line, "r2"), 10_000)) {
                c.open(10_000);
                c.startPulses();
                while (c.nextSip(5000) != null) {
                    // to the end of the run
                }
            }
            assertEquals(0, env.awaitExit(60), env.output());
            // it left before r2's client came, so before the run started; on a very busy machine a step may come first
            assertTrue(env.output().matches("(?s).*robot r1: pose \\(3000, 3000, 0\\.0\\) travelled 0 mm, collisions 0,"
                    + " its ARIA client left (before the run started|after step \\d+) \\(the client sent CLOSE\\);"
                    + " the robot stood still from then to the end\n.*"), env.output());
            assertTrue(env.output().contains("travelled 0 mm, collisions 0, ran to the end"), env.output());
        }
    }

    private static int port(String line, String robot) {
        Matcher m = Pattern.compile(robot + "=(\\d+)").matcher(line);
        assertTrue(m.find(), line);
        return Integer.parseInt(m.group(1));
    }
}
