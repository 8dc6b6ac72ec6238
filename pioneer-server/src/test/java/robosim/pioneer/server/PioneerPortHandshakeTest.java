package robosim.pioneer.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.hw.HardwareOptions;
import robosim.pioneer.Commands;
import robosim.pioneer.ConfigPacket;
import robosim.pioneer.PioneerClient;
import robosim.pioneer.Sip;

/**
 * The port answers ARIA's handshake and keeps its link alive without waiting on the Environment: here
 * an "Environment" that takes the robot's connection and never welcomes it.
 */
@Timeout(value = 1, unit = TimeUnit.MINUTES)
class PioneerPortHandshakeTest {
    /** ARIA's patience for each SYNC answer and for the CONFIG reply, ms. */
    static final int ARIA_REPLY_MS = 1000;
    /** ARIA drops a robot whose status has not come for this long, ms. */
    static final int ARIA_ODOMETRY_MS = 8000;

    private SilentEnvironment silentEnvironment;

    private int silentEnvironment() throws IOException {
        silentEnvironment = new SilentEnvironment();
        return silentEnvironment.port();
    }

    @AfterEach
    void close() throws IOException {
        if (silentEnvironment != null) {
            silentEnvironment.close();
        }
    }

    private static ServedRobot robot(int stepMs) {
        return SilentEnvironment.robot(stepMs);
    }

    @Test
    void handshakeConfigAndStatusPacketsComeWhileTheEnvironmentHasNotWelcomedTheRobot() throws Exception {
        int env = silentEnvironment();
        try (PioneerPorts ports = PioneerPorts.open(List.of(robot(50)), new PioneerPortOptions("127.0.0.1", 0, false,
                PioneerPortOptions.DEFAULT_WATCHDOG_MS, true, HardwareOptions.defaults()), "127.0.0.1", env, null,
                code -> { });
             PioneerClient c = PioneerClient.connect("127.0.0.1", ports.portOf("r1"), ARIA_REPLY_MS)) {
            assertEquals("p3dx", c.identity().subclass());
            ConfigPacket config = c.open(ARIA_REPLY_MS);
            assertEquals("SIM", config.serial(), "ARIA learns that the robot is simulated");
            assertEquals(50, config.sipCycle(), "the world's step length, before the Environment says it");
            assertTrue(silentEnvironment.heardFrom(30, TimeUnit.SECONDS), "the robot asked the Environment to join meanwhile");
            c.startPulses();
            c.send(Commands.comInt(Commands.BATTERYINFO, 1));
            c.send(Commands.comInt(Commands.ENABLE, 1));
            c.send(Commands.comInt(Commands.VEL, 300));
            for (int i = 0; i < 20; i++) {
                Sip s = c.nextSip(ARIA_ODOMETRY_MS);
                assertNotNull(s, "status packet " + i + " while the robot waits for its welcome");
                assertEquals(0, s.xPos());
                assertEquals(0, s.yPos());
                assertEquals(0, s.th());
                assertEquals(0, s.leftVel(), "it stands: commands wait for the robot's first step");
                assertEquals(false, s.moving());
            }
            assertTrue(!c.isClosed(), "the client is still connected");
            assertEquals(0, ports.unattended("r1").map(String::length).orElse(0), "a client drives it");
        }
    }

    /** The silence a client is allowed here, ms: shorter than a port's 15 s, the rule the same. */
    private static final long SILENT_MS = 3_000;

    @Test
    void aClientSilentForLongKeepsItsPortUntilAnotherClientWantsIt() throws Exception {
        int env = silentEnvironment();
        // the robot waits for its welcome longer than the test lasts
        HardwareOptions patient = new HardwareOptions(120_000, HardwareOptions.DEFAULT_LOST_AFTER_MS, 5_000);
        PioneerPortOptions options = new PioneerPortOptions("127.0.0.1", 0, false,
                PioneerPortOptions.DEFAULT_WATCHDOG_MS, true, patient).withPatience(
                PioneerPortOptions.DEFAULT_HANDSHAKE_MS, SILENT_MS);
        try (PioneerPorts ports = PioneerPorts.open(List.of(robot(100)), options, "127.0.0.1", env, null, code -> { });
             PioneerClient first = PioneerClient.connect("127.0.0.1", ports.portOf("r1"), ARIA_REPLY_MS)) {
            first.open(ARIA_REPLY_MS);
            // no PULSE from here, as an ARIA program that has connected its robot but not yet run its cycle
            long until = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(SILENT_MS + 2000);
            while (System.nanoTime() < until) {
                assertNotNull(first.nextSip(ARIA_ODOMETRY_MS), "the silent client is still sent its robot's status");
            }
            assertTrue(!first.isClosed(), "silence alone does not close a client");
            try (PioneerClient second = PioneerClient.connect("127.0.0.1", ports.portOf("r1"), 10_000)) {
                assertEquals("SIM", second.open(ARIA_REPLY_MS).serial(), "the next client gets the port");
                Sip s = first.nextSip(ARIA_ODOMETRY_MS);
                for (int i = 0; i < 100 && s != null; i++) {
                    s = first.nextSip(ARIA_ODOMETRY_MS);
                }
                assertTrue(first.isClosed(), "the silent client gave way");
            }
        }
    }
}
