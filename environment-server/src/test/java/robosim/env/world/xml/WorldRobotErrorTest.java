package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Robots that cannot start where the world file puts them, or cannot be built. */
class WorldRobotErrorTest {
    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    private static String world(String robots) {
        return """
                <world name="robots" width="6000" height="6000">
                  <polygon points="2000,2000 2600,2000 2600,2600 2000,2600"/>
                  <robot name="r1" type="pioneer" x="1000" y="1000" params="../robots/p3dx.p"/>
                %s</world>
                """.formatted(robots);
    }

    private static String robot(String name, String type, double x, double y, String params) {
        return "  <robot name=\"%s\" type=\"%s\" x=\"%s\" y=\"%s\" params=\"%s\"/>\n"
                .formatted(name, type, Attributes.format(x), Attributes.format(y), params);
    }

    @Test
    void robotOutsideTheWorld() {
        fixtures.fails("small-maze.xml", world(robot("r2", "pioneer", 7000, 500, "../robots/p3dx.p")), 4,
                "robot 'r2' at (7000, 500) is outside the world 6000 x 6000");
    }

    @Test
    void robotWhoseBodyCrossesTheEdge() {
        fixtures.fails("edge.xml", world(robot("r2", "pioneer", 5900, 3000, "../robots/p3dx.p")), 4,
                "robot 'r2' at (5900, 3000) is outside the world");
    }

    @Test
    void robotOverlappingAnObstacle() {
        fixtures.fails("overlap.xml", world(robot("r2", "pioneer", 1850, 2300, "../robots/p3dx.p")), 4,
                "robot 'r2' at (1850, 2300) overlaps the polygon at line 2");
    }

    @Test
    void robotOverlappingABoundaryWall() {
        fixtures.fails("bwall.xml", """
                <world name="bwall" width="6000" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="320" y="3000" params="../robots/p3dx.p"/>
                </world>
                """, 2, "robot 'r1' at (320, 3000) overlaps a boundary wall");
    }

    @Test
    void robotOverlappingAnotherRobot() {
        fixtures.fails("robots.xml", world(robot("r2", "pioneer", 1400, 1000, "../robots/p3dx.p")), 4,
                "robot 'r2' at (1400, 1000) overlaps robot 'r1' at line 3");
    }

    @Test
    void duplicateRobotNames() {
        fixtures.fails("dup.xml", world(robot("r1", "pioneer", 4000, 4000, "../robots/p3dx.p")), 4,
                "duplicate robot name 'r1'", "line 3");
    }

    @Test
    void unknownRobotType() {
        fixtures.fails("type.xml", world(robot("r2", "khepera", 4000, 4000, "../robots/p3dx.p")), 4,
                "robot 'r2' has unknown type 'khepera'", "pioneer, scout");
    }

    @Test
    void missingParameterFileIsNamed() {
        fixtures.fails("noparams.xml", world(robot("r2", "pioneer", 4000, 4000, "../robots/p4.p")), 4,
                "robot 'r2': parameter file ../robots/p4.p does not exist",
                dir.resolve("robots/p4.p").toString());
    }

    @Test
    void aNameThatIsNeitherAFileNorShippedSaysBothRules() {
        WorldFileException e = fixtures.fails("unknown.xml", world(robot("r2", "pioneer", 4000, 4000, "p9dx")), 4,
                "robot 'r2': parameter file p9dx does not exist (looked for " + dir.resolve("environment/p9dx") + ")",
                "params is a path relative to the world file's directory, or the name of a file in "
                        + WorldFixtures.root().resolve("testLoadFiles/robots"),
                "p3at, ", "p3dx, ", "scout");
        assertEquals(4, e.line());
    }

    @Test
    void unreadableParameterFileIsNamed() throws IOException {
        Files.createDirectories(dir.resolve("robots/folder.p"));
        fixtures.fails("unreadable.xml", world(robot("r2", "pioneer", 4000, 4000, "../robots/folder.p")), 4,
                "robot 'r2': parameter file ../robots/folder.p cannot be read");
    }

    @Test
    void brokenParameterFileIsWrapped() {
        fixtures.writeRobot("broken.p", """
                ConfigVersion 2.0
                RobotWidth wide
                """);
        fixtures.fails("broken.xml", world(robot("r2", "pioneer", 4000, 4000, "../robots/broken.p")), 4,
                "robot 'r2': broken parameter file:", "broken.p:2: RobotWidth 'wide' is not a number");
    }

    @Test
    void robotWithoutParameterFile() {
        fixtures.fails("noattr.xml", world("  <robot name=\"r2\" type=\"pioneer\" x=\"4000\" y=\"4000\"/>\n"), 4,
                "missing required attribute params on <robot>");
    }

    @Test
    void errorInAMultiLineRobotNamesItsFirstLine() {
        fixtures.fails("multi.xml", world("""
                  <robot name="r2"
                         type="pioneer"
                         x="9000" y="1000"
                         params="../robots/p3dx.p"/>
                """), 4, "robot 'r2' at (9000, 1000) is outside the world");
    }
}
