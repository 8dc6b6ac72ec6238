package robosim.it;

import robosim.cli.Main;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import robosim.comms.CommsSettings;
import robosim.env.net.Access;
import robosim.env.net.ServerOptions;
import robosim.protocol.RunSecret;

/** The comms settings change while the Environment runs (it is waiting for its robots here). */
@Timeout(value = 1, unit = TimeUnit.MINUTES)
@ExtendWith(NoSecretProperty.class) // another test's --token, given in this JVM, may have left the property set
class CommsUpdateTest {
    @TempDir
    Path tokens;

    @Test
    void theCommsCommandChangesOnlyTheSettingsItNames() throws Exception {
        ServerOptions options = new ServerOptions("127.0.0.1", 0, 0, 1, false, 10_000, 3_000, 0, 4 << 20);
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", options)) {
            int code = run("comms", "--port", Integer.toString(h.server.viewerPort()), "--latency", "3", "--loss", "0.25");
            assertEquals(0, code, "the Environment confirmed");
            CommsSettings s = h.sim.commsSettings();
            assertEquals(3, s.latencySteps());
            assertEquals(0.25, s.lossProbability());
            assertEquals(CommsSettings.DEFAULT.maxMessageBytes(), s.maxMessageBytes(), "unchanged");
        }
    }

    @Test
    void settingsThatBreakARuleAreRefused() throws Exception {
        ServerOptions options = new ServerOptions("127.0.0.1", 0, 0, 1, false, 10_000, 3_000, 0, 4 << 20);
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", options)) {
            assertEquals(1, run("comms", "--port", Integer.toString(h.server.viewerPort()), "--loss", "1.5"));
            assertEquals(CommsSettings.DEFAULT, h.sim.commsSettings());
        }
    }

    @Test
    void withoutTheRunSecretTheSettingsCannotBeChanged() throws Exception {
        String secret = RunSecret.create();
        ServerOptions options = ServerOptions.loopback().withMaxSteps(1).withAccess(Access.secret(secret));
        // no secret file of an earlier run on this port number may be found: the client presents none
        System.setProperty(RunSecret.DIR_PROPERTY, tokens.toString());
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", options)) {
            String port = Integer.toString(h.server.viewerPort());
            StringWriter err = new StringWriter();
            CommandLine cl = Main.commandLine();
            cl.setOut(new PrintWriter(new StringWriter()));
            cl.setErr(new PrintWriter(err, true));

            assertEquals(1, cl.execute("comms", "--port", port, "--loss", "1"));
            assertTrue(err.toString().startsWith("robosim comms: the Environment refused: control client comms"
                    + " presented no run secret"), err.toString());
            assertEquals(CommsSettings.DEFAULT, h.sim.commsSettings());

            try {
                assertEquals(0, run("comms", "--port", port, "--token", secret, "--latency", "2"));
                assertEquals(2, h.sim.commsSettings().latencySteps());
            } finally {
                System.clearProperty(RunSecret.PROPERTY);
            }
        } finally {
            System.clearProperty(RunSecret.DIR_PROPERTY);
        }
    }

    @Test
    void nothingToChangeIsACommandLineError() {
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setErr(new PrintWriter(err));
        assertEquals(2, cl.execute("comms", "--port", "1"));
        assertTrue(err.toString().contains("give at least one setting"));
    }

    private static int run(String... args) {
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(new StringWriter()));
        cl.setErr(new PrintWriter(new StringWriter()));
        return cl.execute(args);
    }
}
