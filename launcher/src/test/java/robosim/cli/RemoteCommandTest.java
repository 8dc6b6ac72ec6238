package robosim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** {@code robosim remote}'s command line, refused before any window or connection (the window is tested in remote-control). */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class RemoteCommandTest {
    @TempDir
    Path dir;

    @Test
    void scoutAndParamsAndViewerPortAreRead() {
        CommandLine cl = Main.commandLine();
        cl.parseArgs("remote", "--scout", "--params", "scout.p", "--viewer-port", "4001", "s1", "10.0.0.5", "4000");
        RemoteCommand remote = cl.getSubcommands().get("remote").getCommand();
        assertTrue(remote.scout);
        assertEquals("scout.p", remote.params);
        assertEquals(4001, remote.viewerPort);
        assertEquals("10.0.0.5", remote.host);
        assertEquals(4000, remote.port);
    }

    @Test
    void anUnknownTypeIsRefused() {
        Run run = Run.execute("remote", "--type", "drone", "r1", "localhost", "4000");
        assertEquals(2, run.exit());
        assertEquals("robosim remote: 'drone' was supplied for --type: it is pioneer or scout", run.firstLine());
        run.assertHintToHelp("robosim remote");
    }

    @Test
    void keydriveIsRead() {
        CommandLine cl = Main.commandLine();
        cl.parseArgs("remote", "--keydrive", "r1", "localhost", "4000");
        RemoteCommand remote = cl.getSubcommands().get("remote").getCommand();
        assertTrue(remote.keydrive);
    }

    @Test
    void keydriveForAScoutIsRefused() {
        Run run = Run.execute("remote", "--scout", "--keydrive", "s1", "localhost", "4000");
        assertEquals(2, run.exit());
        assertEquals("robosim remote: --keydrive was given for a Scout: the keydrive action is ARIA's, a Pioneer's",
                run.firstLine());
    }

    @Test
    void aPortOutOfRangeIsRefused() {
        Run run = Run.execute("remote", "r1", "localhost", "70000");
        assertEquals(2, run.exit());
        assertEquals("robosim remote: 70000 was supplied for PORT: a port is 1 to 65535", run.firstLine());
    }

    @Test
    void aParameterFileThatIsNotThereIsNamed() {
        Run run = Run.execute("remote", "--params", dir.resolve("none.p").toString(), "r1", "localhost", "4000");
        assertEquals(2, run.exit());
        assertTrue(run.firstLine().startsWith("robosim remote: --params: ") && run.firstLine().contains("none.p"), run.err());
        run.assertNoStackTrace();
    }

    @Test
    void aSecretFileHoldingNoSecretIsRefused() throws Exception {
        Path file = Files.writeString(dir.resolve("secret"), "short\n");
        Run run = Run.execute("remote", "--secret-file", file.toString(), "r1", "localhost", "4000");
        assertEquals(2, run.exit());
        assertTrue(run.firstLine().startsWith("robosim remote: '" + file + "' was supplied for --secret-file: "), run.err());
    }

    @Test
    void aSecretFileThatCannotBeReadIsRefused() {
        Path file = dir.resolve("missing");
        Run run = Run.execute("remote", "--secret-file", file.toString(), "r1", "localhost", "4000");
        assertEquals(2, run.exit());
        assertTrue(run.firstLine().startsWith("robosim remote: '" + file + "' was supplied for --secret-file: it cannot be read"), run.err());
    }
}
