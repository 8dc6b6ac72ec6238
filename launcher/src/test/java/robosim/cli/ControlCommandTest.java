package robosim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import picocli.CommandLine;

/** {@code robosim control}'s command line, without an Environment (the live runs are in the integration tests). */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class ControlCommandTest {
    @Test
    void negativeCoordinatesAreArgumentsNotOptions() {
        CommandLine cl = Main.commandLine();
        cl.parseArgs("control", "--viewer-port", "4000", "move", "r1", "-500", "-1.5", "-90");
        ControlCommand control = cl.getSubcommands().get("control").getCommand();

        assertEquals("move", control.op);
        assertEquals(List.of("r1", "-500", "-1.5", "-90"), control.args);
        assertEquals(4000, control.at.port());
    }

    @Test
    void withoutAnOperationTheCommandLineIsRefused() {
        Run run = Run.execute("control", "--viewer-port", "4000");

        assertEquals(2, run.exit());
        assertTrue(run.firstLine().contains("Missing required parameter: 'OPERATION'"), run.err());
        run.assertHintToHelp("robosim control");
    }

    @Test
    void aTimeoutOutOfRangeIsRefused() {
        Run run = Run.execute("control", "--timeout", "0", "pause");

        assertEquals(2, run.exit());
        assertEquals("robosim control: --timeout: from 1 to 3600 seconds, got 0", run.firstLine());
    }

    @Test
    void anEnvironmentThatIsNotThereIsOneLineAndExitOne() throws Exception {
        int port;
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            port = s.getLocalPort();
        }
        Run run = Run.execute("control", "--host", "127.0.0.1", "--viewer-port", Integer.toString(port), "--token",
                "abcdefghijklmnop", "--timeout", "1", "pause");

        assertEquals(1, run.exit());
        // it tried again while nothing listened (an Environment may be starting), for its --timeout
        assertTrue(run.firstLine().endsWith("(tried for 1 s, --timeout)"), run.err());
        assertTrue(run.firstLine().startsWith("robosim control: cannot reach the Environment at 127.0.0.1:" + port),
                run.err());
        run.assertNoStackTrace();
    }
}
