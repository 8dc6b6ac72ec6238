package robosim.env.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.core.Simulation;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;

/** Which world files a control client's {@code load} may make the Environment read, and what it refuses. */
class WorldLoaderTest {
    private static final String ROOM = """
            <world name="%s" width="4000" height="4000">
              <wall x1="0" y1="2000" x2="1000" y2="2000"/>
            </world>
            """;

    @TempDir
    Path dir;
    private Path worlds;
    private WorldLoader loader;

    @BeforeEach
    void setUp() throws IOException {
        worlds = Files.createDirectories(dir.resolve("worlds"));
        Path started = Files.writeString(worlds.resolve("first.xml"), ROOM.formatted("first"));
        Files.createDirectories(worlds.resolve("more"));
        Files.writeString(worlds.resolve("more/second.xml"), ROOM.formatted("second"));
        loader = new WorldLoader(new CurrentRun(new Simulation(WorldReader.read(started))), 10);
    }

    private String refusal(String path) {
        return assertThrows(IllegalArgumentException.class, () -> loader.read(path)).getMessage();
    }

    @Test
    void aWorldBesideOrBelowTheStartingWorldIsRead() {
        World w = loader.read("more/second.xml");

        assertEquals("second", w.name());
    }

    @Test
    void aWorldOutsideTheStartingWorldsDirectoryIsRefused() throws IOException {
        Files.writeString(dir.resolve("outside.xml"), ROOM.formatted("outside"));

        assertEquals("load: ../outside.xml is outside " + worlds + ", the directory of the world this Environment"
                + " was started with; load reads world files there only", refusal("../outside.xml"));
        assertTrue(refusal(dir.resolve("outside.xml").toString()).contains("is outside"));
    }

    @Test
    void aLinkThatLeadsOutOfTheDirectoryIsRefused() throws IOException {
        Path outside = Files.writeString(dir.resolve("outside.xml"), ROOM.formatted("outside"));
        Files.createSymbolicLink(worlds.resolve("link.xml"), outside);

        assertTrue(refusal("link.xml").startsWith("load: link.xml is outside "), refusal("link.xml"));
    }

    @Test
    void aPathOutsideIsRefusedAsOutsideWhetherOrNotAFileIsThere() {
        assertTrue(refusal("../no-such-file.xml").startsWith("load: ../no-such-file.xml is outside "),
                refusal("../no-such-file.xml"));
    }

    @Test
    void aMissingFileIsRefusedNamingIt() {
        assertEquals("load: no world file nothing.xml in " + worlds, refusal("nothing.xml"));
    }

    @Test
    void aBrokenWorldIsRefusedWithTheReadersErrorNamingTheFileAndLine() throws IOException {
        Files.writeString(worlds.resolve("broken.xml"), """
                <world name="broken" width="4000" height="4000">
                  <wall x1="0" y1="2000" x2="1000"/>
                </world>
                """);

        String refusal = refusal("broken.xml");

        assertTrue(refusal.startsWith("load: ") && refusal.contains("broken.xml:2: ")
                && refusal.contains("missing required attribute y2"), refusal);
    }

    @Test
    void anEnvironmentNotStartedFromAFileLoadsNothing() throws IOException {
        World made = WorldReader.read(worlds.resolve("first.xml"));
        World sourceless = new World(made.name(), null, made.width(), made.height(), made.stepMs(), made.obstacles(),
                made.robots());
        WorldLoader none = new WorldLoader(new CurrentRun(new Simulation(sourceless)), 10);

        assertEquals("load: this Environment was not started from a world file, so it has no directory to load worlds"
                + " from", assertThrows(IllegalArgumentException.class, () -> none.read("first.xml")).getMessage());
    }
}
