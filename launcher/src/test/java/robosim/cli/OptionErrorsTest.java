package robosim.cli;

import static robosim.cli.Run.execute;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import picocli.CommandLine;

/**
 * The launcher's answers to a bad command line: one line naming what is wrong (the option, the
 * value, the rule, or the name meant), then a pointer to --help, exit 2; and the messages of a run
 * that cannot start say which port and in the unit given.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class OptionErrorsTest {
    @TempDir
    Path dir;



    /** Checks the shape every bad command line gets: a line, then the pointer to --help, exit 2. */
    private static String oneLineThenHelp(Run r, String command) {
        assertEquals(2, r.exit(), r.err());
        assertEquals(2, r.errLines().size(), "one line, then the pointer to --help:\n" + r.err());
        assertEquals("Try '" + command + " --help'.", r.errLines().get(1), r.err());
        assertFalse(r.err().contains("Usage:"), r.err());
        assertEquals("", r.out());
        return r.errLines().get(0);
    }

    @ParameterizedTest
    @CsvSource({"evn, env", "demi, demo", "robto, robot", "veiwer, viewer", "gold-finder, goldfinder"})
    void aMistypedCommandGetsDidYouMean(String typed, String meant) {
        String line = oneLineThenHelp(execute(typed), "robosim");
        assertEquals("robosim: '" + typed + "' is not a command; did you mean " + meant + "?", line);
    }

    @Test
    void anUnknownWordListsTheCommands() {
        String line = oneLineThenHelp(execute("xyzzy"), "robosim");
        assertTrue(line.startsWith("robosim: 'xyzzy' is not a command (the commands are env, robot, viewer"), line);
    }

    @Test
    void aMistypedOptionGetsDidYouMean() {
        String line = oneLineThenHelp(execute("env", "--robto-port", "5000", emptyRoom()), "robosim env");
        assertEquals("robosim env: unknown option '--robto-port'; did you mean --robot-port?", line);
    }

    @ParameterizedTest
    @CsvSource({"--port", "--robot-port", "--viewer-port"})
    void aPortThatIsNotANumberIsOneLineNamingTheOptionAndTheValue(String option) {
        String line = oneLineThenHelp(execute("env", option, "abc", emptyRoom()), "robosim env");
        assertEquals("robosim env: Invalid value for option '" + option + "': 'abc' is not an int", line);
    }

    @Test
    void aBadValueInAClientCommandIsOneLineToo() {
        String line = oneLineThenHelp(execute("viewer", "--viewer-port", "x", "--window"), "robosim viewer");
        assertEquals("robosim viewer: Invalid value for option '--viewer-port': 'x' is not an int", line);
    }

    @Test
    void aClasspathEntryThatDoesNotExistIsFlagged() {
        Path nowhere = dir.resolve("nowhere");
        String line = oneLineThenHelp(execute("robot", "--classpath", nowhere.toString(), "no.Such", "r1", "127.0.0.1",
                "5000"), "robosim robot");
        assertEquals("robosim robot: '" + nowhere + "' was supplied for --classpath: there is no such directory or jar",
                line);
    }

    @Test
    void aBusyRobotPortIsNamedAsTheRobotPort() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            Run r = execute("env", "--robot-port", Integer.toString(taken.getLocalPort()), "--viewer-port", "0",
                    "--no-token", emptyRoom());
            assertEquals(1, r.exit(), r.err());
            assertEquals("robosim env: cannot listen on the robot port 127.0.0.1:" + taken.getLocalPort() + ": ",
                    r.err().strip().substring(0, r.err().indexOf(": ", r.err().indexOf(taken.getLocalPort() + "")) + 2));
            assertTrue(r.err().strip().endsWith("(--robot-port and --viewer-port choose others; 0 takes any free port)"),
                    r.err());
        }
    }

    @Test
    void aBusyViewerPortIsNamedAsTheViewerPort() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            Run r = execute("env", "--robot-port", "0", "--viewer-port", Integer.toString(taken.getLocalPort()),
                    "--no-token", emptyRoom());
            assertEquals(1, r.exit(), r.err());
            assertTrue(r.err().startsWith("robosim env: cannot listen on the viewer port 127.0.0.1:" + taken.getLocalPort()
                    + ": "), r.err());
            assertEquals(1, r.errLines().size(), r.err());
        }
    }

    @Test
    void theConnectTimeoutIsReportedInSecondsAsGiven() {
        Run r = execute("env", "--robot-port", "0", "--viewer-port", "0", "--no-token", "--connect-timeout", "1",
                emptyRoom());
        assertEquals(1, r.exit(), r.err());
        assertTrue(r.err().strip().endsWith("did not connect within 1 s"), r.err());
    }

    @Test
    void aRobotThatCannotConnectIsToldOnce() throws Exception {
        int closed;
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            closed = s.getLocalPort();
        }
        List<String> logged = new CopyOnWriteArrayList<>();
        Handler capture = new Handler() {
            @Override
            public void publish(LogRecord record) {
                logged.add(record.getMessage());
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        Logger hw = Logger.getLogger("robosim.hw");
        hw.addHandler(capture);
        try {
            Run r = execute("robot", "--lost-after", "1000", "--environment-timeout", "1", DemoCommand.WANDER, "r1",
                    "127.0.0.1", Integer.toString(closed));
            assertEquals(1, r.exit(), r.err());
            long told = logged.stream().filter(m -> m.contains("could not connect")).count()
                    + r.err().lines().filter(l -> l.contains("could not connect")).count();
            assertEquals(1, told, "logged: " + logged + "\nprinted: " + r.err());
        } finally {
            hw.removeHandler(capture);
        }
    }

    @Test
    void theOldNamesStillWork() {
        CommandLine cl = Main.commandLine();
        cl.parseArgs("goldfinder", "w.xml", "--out", "old-dir", "--max-steps", "7");
        GoldfinderCommand gold = cl.getSubcommands().get("goldfinder").getCommand();
        assertEquals(Path.of("old-dir"), gold.oldOut);
        assertEquals(7, gold.oldMaxSteps);

        cl = Main.commandLine();
        cl.parseArgs("demo", "--out", "d", "--max-steps", "8");
        DemoCommand demo = cl.getSubcommands().get("demo").getCommand();
        assertEquals(Path.of("d"), demo.oldOut);
        assertEquals(8, demo.oldMaxSteps);

        cl = Main.commandLine();
        cl.parseArgs("comms", "--port", "4000");
        CommsCommand comms = cl.getSubcommands().get("comms").getCommand();
        assertEquals(4000, comms.at.port());
    }

    @Test
    void goldfinderTakesItsOldNamesForTheFolderAndTheStepLimit() {
        Path old = dir.resolve("old-out");
        Run r = execute("goldfinder", root().resolve("testLoadFiles/environment/maze-small.xml").toString(), "--robots", "1",
                "--no-frames", "--out", old.toString(), "--max-steps", "2");
        assertEquals(GoldfinderCommand.NOT_FOUND, r.exit(), r.out() + r.err());
        assertTrue(Files.isDirectory(old.resolve("frames")), "--out still names the folder");
        assertTrue(r.out().contains("Gold not found: step limit 2 reached"), "--max-steps is still the limit:\n" + r.out());
    }

    private static String emptyRoom() {
        return root().resolve("testLoadFiles/environment/empty-room.xml").toString();
    }

    private static Path root() {
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (p != null && !Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        return p;
    }

    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.CsvSource({"--every, 0, 1", "--steps, -1, 0", "--robots, 0, 1"})
    void goldfinderRefusesABadValueBeforeItsRunWithOneLine(String option, String value, String least) {
        Path maze = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (!maze.resolve("testLoadFiles").toFile().isDirectory()) {
            maze = maze.getParent();
        }
        Run r = execute("goldfinder", maze.resolve("testLoadFiles/environment/maze-small.xml").toString(), option, value);

        assertEquals(2, r.exit(), r.err());
        assertEquals(List.of("robosim goldfinder: " + value + " was supplied for " + option + ": it must be at least "
                + least, "Try 'robosim goldfinder --help'."), r.errLines());
    }
}
