package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.world.World;

/** The {@code <gold>} element. */
class WorldGoldTest {
    @TempDir
    Path dir;

    private Path world(String body) throws Exception {
        Path f = dir.resolve("gold.xml");
        Files.writeString(f, "<world name=\"g\" width=\"6000\" height=\"6000\">\n" + body + "</world>\n");
        return f;
    }

    @Test
    void theGoldIsReadAndGlows() throws Exception {
        World w = WorldReader.read(world("  <heat x=\"100\" y=\"100\" intensity=\"5\"/>\n  <gold x=\"3000\" y=\"4000\" intensity=\"50\"/>\n"));
        assertEquals(3000, w.gold().x());
        assertEquals(4000, w.gold().y());
        assertEquals(50, w.gold().intensity());
        assertEquals(3, w.gold().line());
        assertEquals(2, w.heat().size(), "the gold is a heat source too");
        assertTrue(w.heat().contains(w.gold()));
    }

    @Test
    void aWorldWithoutGoldHasNone() throws Exception {
        assertNull(WorldReader.read(world("")).gold());
    }

    @Test
    void aSecondGoldIsRefused() throws Exception {
        WorldFileException e = assertThrows(WorldFileException.class, () -> WorldReader.read(
                world("  <gold x=\"1000\" y=\"1000\" intensity=\"50\"/>\n  <gold x=\"2000\" y=\"1000\" intensity=\"50\"/>\n")));
        assertTrue(e.getMessage().endsWith("gold.xml:3: a world has at most one <gold>; the first is at line 2"), e.getMessage());
    }

    @Test
    void goldOutsideTheWorldIsRefused() throws Exception {
        WorldFileException e = assertThrows(WorldFileException.class,
                () -> WorldReader.read(world("  <gold x=\"7000\" y=\"1000\" intensity=\"50\"/>\n")));
        assertTrue(e.getMessage().contains("gold.xml:2: gold at (7000, 1000) is outside the world"), e.getMessage());
    }
}
