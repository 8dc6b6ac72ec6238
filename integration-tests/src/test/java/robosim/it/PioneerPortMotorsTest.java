package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.world.xml.WorldReader;
import robosim.pioneer.Commands;
import robosim.pioneer.PioneerClient;
import robosim.pioneer.Sip;

/**
 * The motors of a robot on a Pioneer port: an ARIA client's ENABLE switches the robot's motors in the
 * Environment, which ignores motion while they are off and stops the robot at ENABLE 0; the SIP's
 * flags bit 0 reports them.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class PioneerPortMotorsTest {
    @TempDir
    Path dir;

    /** Reads SIPs until one has the motors flag as asked; fails after 40. */
    private static Sip untilMotors(PioneerClient c, boolean on) {
        for (int i = 0; i < 40; i++) {
            Sip s = c.nextSip(2000);
            assertNotNull(s, "a SIP every step");
            if (((s.flags() & Sip.FLAG_MOTORS) != 0) == on) {
                return s;
            }
        }
        throw new AssertionError("no SIP with the motors " + (on ? "on" : "off") + " in 40");
    }

    @Test
    void velBeforeEnableIsIgnoredEnableLetsItDriveAndEnableZeroStops() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), false, code -> { });
             PioneerClient c = run.client("r1")) {
            PioneerPortTest.settled(c);
            c.send(Commands.comInt(Commands.VEL, 300));
            for (int i = 0; i < 10; i++) {
                Sip s = c.nextSip(2000);
                assertEquals(0, s.flags() & Sip.FLAG_MOTORS, "the motors are off until ENABLE 1");
                assertEquals(0, s.leftVel() + s.rightVel(), "VEL is ignored while they are off");
            }
            assertEquals(3000, run.env.sim.summary("r1").x(), 1e-9);

            c.send(Commands.comInt(Commands.ENABLE, 1));
            c.send(Commands.comInt(Commands.VEL, 300));
            Sip moving = null;
            for (int i = 0; i < 40 && (moving == null || moving.leftVel() != 300); i++) {
                moving = c.nextSip(2000);
            }
            assertEquals(300, moving.leftVel());
            assertEquals(Sip.FLAG_MOTORS, moving.flags() & Sip.FLAG_MOTORS);

            c.send(Commands.comInt(Commands.ENABLE, 0));
            Sip off = untilMotors(c, false);
            assertEquals(0, off.leftVel() + off.rightVel(), "ENABLE 0 stops the robot at once");
            double x = run.env.sim.summary("r1").x();
            assertTrue(x > 3000, "it drove while enabled: " + x);
        }
    }

    @Test
    void aWorldWithMotorsEnabledHasTheClientFindThemOn() throws Exception {
        Path world = dir.resolve("on.xml");
        Files.writeString(world, """
                <world name="room" width="10000" height="10000" boundary="true" motors="enabled">
                  <robot name="r1" type="pioneer" x="3000" y="3000" th="0" params="%s"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p")));
        try (PioneerRun run = new PioneerRun(WorldReader.read(world), false, code -> { });
             PioneerClient c = run.client("r1")) {
            untilMotors(c, true);
            c.send(Commands.comInt(Commands.VEL, 200));
            Sip moving = null;
            for (int i = 0; i < 40 && (moving == null || moving.leftVel() != 200); i++) {
                moving = c.nextSip(2000);
            }
            assertEquals(200, moving.leftVel(), "no ENABLE needed in this world");
        }
    }
}
