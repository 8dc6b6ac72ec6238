package robosim.env.world.maze;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;
import robosim.params.RobotParameterFiles;

/** The lower bound a team searching a maze for gold is measured against: the shortest path driven at top speed. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class GoldBoundTest {
    @TempDir
    Path dir;

    private World world(Maze maze, int robots) throws Exception {
        Path file = dir.resolve("maze.xml");
        Files.writeString(file, MazeWorldWriter.write(maze, "m", 1500, robots,
                RobotParameterFiles.root().resolve("testLoadFiles/robots/p3dx.p").toAbsolutePath().toString()),
                StandardCharsets.UTF_8);
        return WorldReader.read(file);
    }

    @Test
    void aStraightCorridorIsOneRunThatEndsAMetreShortOfTheGold() throws Exception {
        // 5 x 1: the gold four cells (6000 mm) east of r1; found 1000 mm short, so 5000 mm from rest
        // to rest at 300 mm/s/s (the top speed, 2200 mm/s, is not reached): 2 sqrt(5000 / 300) s
        Maze corridor = Maze.generate(5, 1, 1);
        assertEquals(82, GoldBound.steps(corridor, world(corridor, 1), 1500));
        // r2 starts a cell nearer: 3500 mm, 2 sqrt(3500 / 300) = 6.83 s
        assertEquals(69, GoldBound.steps(corridor, world(corridor, 2), 1500));
    }

    @Test
    void eachCornerAddsATurnInPlace() throws Exception {
        // 2 x 2 seed 1: the path from (0, 0) to the farthest cell has two corners (three runs of one cell)
        Maze square = Maze.generate(2, 2, 1);
        int[][] d = square.distancesFrom(0, 0);
        assertEquals(3, Math.max(Math.max(d[0][1], d[1][0]), d[1][1]), "a perfect 2 x 2 maze is a path of 4 cells");
        // two runs of 1500 mm (2 sqrt(1500 / 300) = 4.472 s each), the last of 1500 - 1000 = 500 mm
        // (2.582 s), two 90° turns of 2 sqrt(90 / 100) = 1.897 s each: 15.32 s
        assertEquals(154, GoldBound.steps(square, world(square, 1), 1500));
    }
}
