package robosim.env.world.maze;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/** The world files {@link MazeWorldWriter} writes, and the shipped mazes it wrote. */
class MazeWorldWriterTest {
    @Test
    void theCellSizeIsAWorldPropertyRightAfterTheWorldElement() {
        String xml = MazeWorldWriter.write(Maze.generate(3, 3, 5), "m", 1250, 2, "../robots/p3dx.p");

        String[] lines = xml.split("\n");
        assertTrue(lines[2].startsWith("<world name=\"m\" width=\"3750\" height=\"3750\""), lines[2]);
        assertEquals("  <property name=\"cellSize\" value=\"1250\"/>", lines[3]);
    }

    /** The shipped mazes are the writer's own output, so they carry the cell size robot programs read. */
    @ParameterizedTest
    @CsvSource({"maze-small.xml, 5, 11, 8", "maze-medium.xml, 10, 12, 8", "maze-large.xml, 20, 13, 8"})
    void theShippedMazesAreWhatTheWriterWritesForTheirSeeds(String file, int size, long seed, int robots)
            throws IOException {
        String shipped = Files.readString(root().resolve("testLoadFiles/environment").resolve(file));
        String name = "maze-" + size + "x" + size + "-" + seed;

        assertEquals(MazeWorldWriter.write(Maze.generate(size, size, seed), name, 1500, robots, "../robots/p3dx.p"),
                shipped);
    }

    private static Path root() {
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (p != null && !Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        assertTrue(p != null, "no testLoadFiles above " + System.getProperty("robosim.root", ""));
        return p;
    }
}
