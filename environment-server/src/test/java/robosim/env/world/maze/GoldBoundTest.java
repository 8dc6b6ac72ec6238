package robosim.env.world.maze;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;
import robosim.params.RobotParameterFiles;
import robosim.protocol.RobotParameters;

/**
 * The lower bound on the steps to find a world's gold: the shortest path around the walls, driven
 * from rest at top speed, against figures worked out by hand.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class GoldBoundTest {
    @TempDir
    Path dir;
    private String params;

    @BeforeEach
    void pioneer() throws Exception {
        Path file = RobotParameterFiles.root().resolve("testLoadFiles/robots/p3dx.p").toAbsolutePath();
        params = file.toString().replace('\\', '/');
        RobotParameters p = RobotParameterFiles.load(file.toString());
        // the figures below are worked out for these
        assertEquals(2200, p.maxVelocity());
        assertEquals(300, p.transAccel());
        assertEquals(210, GoldBound.innerRadius(p), "the body's front is its nearest side to the centre");
    }

    private World maze(Maze maze, int robots) throws Exception {
        Path file = dir.resolve("maze.xml");
        Files.writeString(file, MazeWorldWriter.write(maze, "m", 1500, robots, params), StandardCharsets.UTF_8);
        return WorldReader.read(file);
    }

    @Test
    void aStraightCorridorIsDrivenFromRestToAMetreShortOfTheGold() throws Exception {
        // 5 x 1: the gold four cells (6000 mm) east of r1; found 1000 mm short, so 5000 mm from rest
        // at 300 mm/s/s (top speed, 2200 mm/s, needs 8067 mm): sqrt(2 * 5000 / 300) = 5.77 s, step 58,
        // less one for the step's discretisation
        Maze corridor = Maze.generate(5, 1, 1);
        assertEquals(57, GoldBound.steps(maze(corridor, 1)));
        // r2 starts a cell nearer: 3500 mm, sqrt(2 * 3500 / 300) = 4.83 s
        assertEquals(48, GoldBound.steps(maze(corridor, 2)));
    }

    @Test
    void aWallInTheWayIsPassedByItsNearestEndHuggingTheRobotsWidth() throws Exception {
        // a wall x = 4000 from y = 0 to 4000, 100 mm thick with square caps: its top corners are
        // (3950, 4050) and (4050, 4050); the robot's centre keeps 210 mm from it, so the path is a
        // tangent from the robot to a circle of 210 mm about the first corner, round it, 100 mm along
        // the top, round the second corner's circle and a tangent down to the gold
        Files.writeString(dir.resolve("wall.xml"), String.format("""
                <world name="wall" width="8000" height="6000" stepMs="100">
                  <wall x1="4000" y1="0" x2="4000" y2="4000"/>
                  <robot name="r1" type="pioneer" x="1000" y="3000" th="0" params="%s"/>
                  <gold x="7000" y="3000" intensity="100"/>
                </world>
                """, params), StandardCharsets.UTF_8);
        double r = 210;
        double dx = 3950 - 1000;
        double dy = 4050 - 3000;
        double centre = Math.hypot(dx, dy);
        double tangent = Math.sqrt(centre * centre - r * r);
        // the tangent leaves the circle at acos(r / centre) from the line to the robot; the path then
        // turns round to the top of the circle
        double toRobot = Math.atan2(-dy, -dx);
        double leaves = toRobot - Math.acos(r / centre) + 2 * Math.PI;
        double arc = (leaves - Math.PI / 2) * r;
        double path = 2 * (tangent + arc) + 100;
        double seconds = Math.sqrt(2 * (path - 1000) / 300);
        long expected = (long) Math.ceil(seconds * 10) - 1;
        assertEquals(60, expected, "the worked figure: " + path + " mm, " + seconds + " s");
        assertEquals(expected, GoldBound.steps(WorldReader.read(dir.resolve("wall.xml"))));
    }

    @Test
    void aMazesBoundLiesBetweenTheStraightLineAndTheCellsPath() throws Exception {
        // 10 x 10 seed 7: the path may cut the corners of the cells' centre line, never the walls
        Maze maze = Maze.generate(10, 10, 7);
        World world = maze(maze, 1);
        double rx = world.robots().get(0).x();
        double ry = world.robots().get(0).y();
        double straight = Math.hypot(world.gold().x() - rx, world.gold().y() - ry);
        int[][] d = maze.distancesFrom((int) (rx / 1500), (int) (ry / 1500));
        double cells = d[(int) (world.gold().x() / 1500)][(int) (world.gold().y() / 1500)] * 1500.0;
        long bound = GoldBound.steps(world);
        long low = (long) Math.ceil(GoldBound.seconds(straight - 1000, 2200, 300) * 10) - 1;
        long high = (long) Math.ceil(GoldBound.seconds(cells - 1000, 2200, 300) * 10) - 1;
        assertTrue(bound > low && bound < high, "bound " + bound + " between " + low + " and " + high);
    }

    @Test
    void aTopSpeedReachedIsHeld() {
        // 10000 mm: 8067 mm to reach 2200 mm/s in 7.33 s, then 1933 mm at 2200 mm/s in 0.879 s
        assertEquals(8.212, GoldBound.seconds(10_000, 2200, 300), 0.001);
    }
}
