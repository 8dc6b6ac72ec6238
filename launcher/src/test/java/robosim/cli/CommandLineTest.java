package robosim.cli;

import static robosim.cli.Run.execute;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The launcher's command line, executed in this JVM with captured writers: help, exit codes 0/1/2,
 * and one-line errors that name the argument, never a stack trace.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class CommandLineTest {
    @TempDir
    Path dir;



    private static String emptyRoom() {
        return root().resolve("testLoadFiles/environment/empty-room.xml").toString();
    }

    @Test
    void helpOfTheTopCommandListsTheSubcommands() {
        Run r = execute("--help");
        assertEquals(0, r.exit(), r.err());
        assertTrue(r.out().startsWith("Usage: robosim "), r.out());
        for (String sub : new String[] {"env", "robot", "viewer", "demo"}) {
            assertTrue(r.out().contains("  " + sub + " "), "lists " + sub + ":\n" + r.out());
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"env", "robot", "viewer", "demo"})
    void helpOfEachSubcommandPrintsItsUsage(String sub) {
        Run r = execute(sub, "--help");
        assertEquals(0, r.exit(), r.err());
        assertTrue(r.out().startsWith("Usage: robosim " + sub), r.out());
        assertTrue(r.out().contains("--help"), r.out());
        assertEquals("", r.err());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "env                      | WORLD",
            "robot                    | CLASS",
            "robot Cls r1 127.0.0.1   | PORT",
            "viewer                   | --png-dir"})
    void aMissingRequiredArgumentExitsWith2AndNamesIt(String args, String missing) {
        Run r = execute(args.split(" "));
        assertEquals(2, r.exit(), r.err());
        assertTrue(r.err().contains("Missing required") && r.err().contains(missing), r.err());
    }

    @Test
    void envWithANonexistentWorldFileExitsWith1AndNamesTheFile() {
        Path missing = dir.resolve("no-such-world.xml");
        Run r = execute("env", missing.toString());
        assertEquals(1, r.exit(), r.err());
        assertTrue(r.err().startsWith("robosim env: ") && r.err().contains(missing.toString()), r.err());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        r.assertNoStackTrace();
    }

    @Test
    void envWithADirectoryForTheWorldFileExitsWith1AndNamesIt() {
        Run r = execute("env", dir.toString());
        assertEquals(1, r.exit(), r.err());
        assertTrue(r.err().startsWith("robosim env: ") && r.err().contains(dir.toString()), r.err());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        r.assertNoStackTrace();
    }

    @Test
    void envWithARobotOutsideTheWorldExitsWith1AndNamesFileAndLine() throws Exception {
        Path p3dx = root().resolve("testLoadFiles/robots/p3dx.p").toAbsolutePath();
        Path world = dir.resolve("outside.xml");
        Files.writeString(world, """
                <?xml version="1.0" encoding="UTF-8"?>
                <world name="outside" width="6000" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="1500" y="1500" params="%s"/>
                  <robot name="r2" type="pioneer" x="9000" y="1000" params="%s"/>
                </world>
                """.formatted(p3dx, p3dx));
        Run r = execute("env", world.toString());
        assertEquals(1, r.exit(), r.err());
        assertTrue(r.err().contains(world + ":4: "), "names file:line of r2:\n" + r.err());
        assertTrue(r.err().contains("outside the world"), r.err());
        r.assertNoStackTrace();
    }

    @ParameterizedTest
    @CsvSource({"--port, -5, --port", "--port, 70000, --port", "--viewer-port, -1, --viewer-port",
            "--connect-timeout, 0, --connect-timeout", "--step-timeout, 0, --step-timeout"})
    void envWithAnInvalidOptionExitsWith2AndSaysWhy(String option, String value, String named) {
        Run r = execute("env", option, value, emptyRoom());
        assertEquals(2, r.exit(), r.err());
        assertEquals("robosim env: " + value + " was supplied for " + named, r.firstLine().replaceAll(":[^:]*$", ""),
                r.err());
        r.assertHintToHelp("robosim env");
        r.assertNoStackTrace();
    }

    @Test
    void envWithNoThreadsExitsWith2AndSaysWhy() {
        Run r = execute("env", "--threads", "0", emptyRoom());
        assertEquals(2, r.exit(), r.err());
        assertEquals("robosim env: 0 was supplied for --threads: it must be at least 1", r.firstLine(), r.err());
        r.assertHintToHelp("robosim env");
        r.assertNoStackTrace();
    }

    @Test
    void envOnAPortInUseExitsWith1AndSaysWhy() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            Run r = execute("env", "--port", Integer.toString(taken.getLocalPort()), "--viewer-port", "0", emptyRoom());
            assertEquals(1, r.exit(), r.err());
            assertTrue(r.err().startsWith("robosim env: cannot listen on the robot port 127.0.0.1:" + taken.getLocalPort()),
                    r.err());
            r.assertNoStackTrace();
        }
    }

    @Test
    void robotWithAClassThatDoesNotExistExitsWith1AndSaysSo() {
        Run r = execute("robot", "no.such.RobotProgram", "r1", "127.0.0.1", "5000");
        assertEquals(1, r.exit(), r.err());
        assertTrue(r.err().startsWith("robosim robot: no class no.such.RobotProgram"), r.err());
        r.assertNoStackTrace();
    }

    @Test
    void robotWithPort70000ExitsWith2AndNamesTheRule() {
        Run r = execute("robot", "no.such.RobotProgram", "r1", "127.0.0.1", "70000");
        assertEquals(2, r.exit(), r.err());
        assertEquals("robosim robot: 70000 was supplied for PORT: a port is 1 to 65535", r.firstLine());
        r.assertHintToHelp("robosim robot");
    }

    @Test
    void robotWithoutHostAndPortExitsWith2AndNamesBothForms() {
        Run r = execute("robot", "no.such.RobotProgram", "r1");
        assertEquals(2, r.exit(), r.err());
        assertEquals("robosim robot: Missing required parameters: 'HOST', 'PORT' (the Environment's, after NAME; or give"
                + " --pioneer HOST:PORT to drive a Pioneer robot server)", r.firstLine());
    }

    @Test
    void robotWithPioneerNeedsNoEnvironmentHostAndPort() {
        Run r = execute("robot", "--pioneer", "127.0.0.1:8101", "no.such.RobotProgram", "r1");
        assertEquals(1, r.exit(), r.err());
        assertTrue(r.err().startsWith("robosim robot: no class no.such.RobotProgram"), r.err());
    }

    @Test
    void robotWithAPioneerServerWithoutPortExitsWith2AndNamesTheRule() {
        Run r = execute("robot", "--pioneer", "127.0.0.1", "no.such.RobotProgram", "r1");
        assertEquals(2, r.exit(), r.err());
        assertEquals("robosim robot: '127.0.0.1' was supplied for --pioneer: a Pioneer robot server is given as"
                + " HOST:PORT, the port 1 to 65535", r.firstLine());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "--robots 0          | 0 was supplied for --robots: counts are 1 to 5000",
            "--robots 10,6000    | 6000 was supplied for --robots: counts are 1 to 5000",
            "--sensors radar     | radar was supplied for --sensors: sensors are sonar or laser",
            "--sensors sonar,sky | sky was supplied for --sensors: sensors are sonar or laser",
            "--clients 0         | 0 was supplied for --clients: client JVMs are 1 to 64",
            "--repeat 0          | 0 was supplied for --repeat: it must be at least 1",
            "--heap-every -1     | -1 was supplied for --heap-every: it must be 0 (none) or more",
            "--rates-every -1    | -1 was supplied for --rates-every: it must be 0 (none) or more",
            "--goldfinder --first-maze 0 | 0 was supplied for --first-maze: it must be at least 1",
            "--goldfinder --mazes 0      | 0 was supplied for --mazes: it must be at least 1",
            "--map-load --map-points 10  | 10 was supplied for --map-points: it must be from 1000 to 5000000",
            "--pioneer-flood --robots 4 --flood-seconds 0 | 0.0 was supplied for --flood-seconds: it must be from 1 to 60"})
    void benchWithAnInvalidOptionExitsWith2AndSaysWhyBeforeMeasuringAnything(String args, String message) {
        java.util.List<String> line = new java.util.ArrayList<>(java.util.List.of("bench", "--out-dir", dir.toString()));
        line.addAll(java.util.List.of(args.split(" ")));
        Run r = execute(line.toArray(String[]::new));
        assertEquals(2, r.exit(), r.err());
        assertEquals("robosim bench: " + message, r.firstLine());
        r.assertHintToHelp("robosim bench");
        assertEquals("", r.out(), "nothing was measured");
        r.assertNoStackTrace();
    }

    /** The RoboSim root: the nearest folder above the working directory that holds testLoadFiles. */
    private static Path root() {
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (p != null && !Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        return p;
    }
}
