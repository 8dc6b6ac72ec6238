package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import robosim.cli.Main;
import robosim.pioneer.Commands;
import robosim.pioneer.PioneerClient;
import robosim.pioneer.Sip;

/** {@code robosim env --pioneer-port} as a user runs it: an ARIA-style client drives a robot of the world. */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class PioneerEnvCommandTest {
    @TempDir
    Path dir;

    @Test
    void envOffersTheWorldsRobotsOnPioneerPortsAndReportsTheRun() throws Exception {
        Path world = dir.resolve("room.xml");
        Files.writeString(world, """
                <world name="room" width="10000" height="10000" boundary="true">
                  <robot name="r1" type="pioneer" x="3000" y="3000" th="0" params="%s"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p")));
        try (LauncherJvm env = new LauncherJvm("env", world.toString(), "--robot-port", "0", "--viewer-port", "0",
                "--pioneer-port", "0", "--steps", "30", "--quiet")) {
            String line = env.awaitLine(l -> l.startsWith("Pioneer ports on 127.0.0.1: "), 60);
            Matcher m = Pattern.compile("r1=(\\d+)").matcher(line);
            assertTrue(m.find(), line);
            int sips = 0;
            try (PioneerClient c = PioneerClient.connect("127.0.0.1", Integer.parseInt(m.group(1)), 10_000)) {
                c.open(10_000);
                c.startPulses();
                c.send(Commands.comInt(Commands.ENABLE, 1));
                c.send(Commands.comInt(Commands.VEL, 200));
                Sip s;
                while ((s = c.nextSip(5000)) != null) {
                    sips++;
                }
            }
            assertEquals(0, env.awaitExit(60), env.output());
            assertTrue(sips >= 25, "a SIP a step: " + sips);
            assertTrue(env.output().contains("Run ended after 30 steps (3.0 s simulated)"), env.output());
            assertTrue(env.output().matches("(?s).*robot r1: pose \\(3\\d\\d\\d, 3000, 0\\.0\\) travelled [1-9]\\d+ mm.*"),
                    env.output());
        }
    }

    @Test
    void thePioneerOptionsNeedThePioneerPort() {
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(new StringWriter()));
        cl.setErr(new PrintWriter(err, true));
        int exit = cl.execute("env", LocalEnvironment.root().resolve("testLoadFiles/environment/empty-room.xml").toString(),
                "--allow-sim-exit");
        assertEquals(2, exit);
        assertTrue(err.toString().startsWith("robosim env: --allow-sim-exit needs --pioneer-port"), err.toString());
    }
}
