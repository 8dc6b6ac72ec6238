package robosim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.cli.Run.execute;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import robosim.env.world.RobotToPlace;

/** {@code robosim env MAP.map --robot TYPE[:NAME]}: maps as worlds, robots asked for on the command line. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class EnvRobotOptionTest {
    private static final String MAP = """
            2D-Map
            Cairn: RobotHome 1000 1000 90 "" ICON "Home"
            LINES
            -3000 -2000 5000 -2000
            5000 4000 -3000 4000
            """;

    @TempDir
    Path dir;

    private Path map() throws IOException {
        Path file = dir.resolve("lab.map");
        Files.writeString(file, MAP);
        return file;
    }

    @Test
    void robotOptionsParseInOrder() {
        CommandLine cl = Main.commandLine();
        CommandLine.ParseResult parsed = cl.parseArgs("env", "--robot", "p3dx", "--robot", "p3at:scout2", "lab.map");
        EnvCommand env = (EnvCommand) parsed.subcommand().commandSpec().userObject();
        assertEquals(List.of(new RobotToPlace("p3dx", null), new RobotToPlace("p3at", "scout2")), env.robotsToPlace());
    }

    @Test
    void anEmptyNameIsAnOptionError() throws IOException {
        Run r = execute("env", "--robot", "p3dx:", map().toString());
        assertEquals(2, r.exit(), r.err());
        assertEquals("robosim env: 'p3dx:' was supplied for --robot: the NAME after ':' is empty (leave out ':' for"
                + " the default name)", r.firstLine());
        r.assertHintToHelp("robosim env");
    }

    @Test
    void anUnknownTypeNamesTheOptionAndExitsWith1() throws IOException {
        Path map = map();
        Run r = execute("env", "--robot", "p9dx", map.toString());
        assertEquals(1, r.exit(), r.err());
        assertTrue(r.firstLine().startsWith("robosim env: " + map + ": --robot p9dx: robot parameter file 'p9dx' not found"),
                r.err());
        r.assertNoStackTrace();
    }

    @Test
    void aMapWaitsForTheRobotsAskedFor() throws IOException {
        Run r = execute("env", "--robot-port", "0", "--viewer-port", "0", "--no-token", "--connect-timeout", "1",
                "--robot", "p3dx", "--robot", "p3at:scout2", map().toString());
        assertEquals(1, r.exit(), r.err());
        assertTrue(r.out().contains("Waiting for robots: p3dx_1, scout2"), r.out());
    }

    @Test
    void aMapWithoutRobotOptionsWaitsForOneP3dx() throws IOException {
        Run r = execute("env", "--robot-port", "0", "--viewer-port", "0", "--no-token", "--connect-timeout", "1",
                map().toString());
        assertTrue(r.out().contains("Waiting for robots: p3dx_1\n") || r.out().contains("Waiting for robots: p3dx_1\r"),
                r.out());
    }

    @Test
    void openAdmitsRobotsTheWorldDoesNotNameAndWaitsForTheFirst() throws IOException {
        Path world = dir.resolve("arena.xml");
        Files.writeString(world, """
                <world name="arena" width="6000" height="6000">
                  <spawn x="1500" y="1500"/>
                  <spawn x="4500" y="1500"/>
                </world>
                """);

        Run r = execute("env", "--robot-port", "0", "--viewer-port", "0", "--no-token", "--connect-timeout", "1",
                "--open", world.toString());

        assertEquals(1, r.exit(), r.err());
        assertTrue(r.out().contains("Open world: robots it does not name join at its 2 spawn pose(s); the run starts at"
                + " the first robot"), r.out());
        assertTrue(r.err().contains("no robot (open world arena) and 0 viewer(s) did not connect within 1 s"), r.err());
    }
}
