package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import java.nio.file.Path;
import robosim.env.world.Bounds;
import robosim.env.world.ForbiddenZone;
import robosim.env.world.RobotToPlace;
import robosim.env.world.RobotSpec;
import robosim.env.world.World;
import robosim.map.MapReader;

/** ARIA maps as worlds: read on their own, or brought into a world file by {@code <map>}. */
class MapWorldTest {
    /** A 8 m x 6 m room around the origin, four points in a row, one alone, one home, two forbidden zones. */
    static final String LAB = """
            2D-Map
            MinPos: 2000 0
            MaxPos: 3000 3000
            NumPoints: 5
            NumLines: 4
            Resolution: 20
            Cairn: RobotHome 1000 1000 90 "" ICON "Home"
            Cairn: Goal 3000 2000 0 "" ICON "G1"
            Cairn: ForbiddenArea 0 0 0.000000 "" ICON "keep out" -2500 2500 -1500 3500
            Cairn: ForbiddenLine 0 0 0.000000 "" ICON "" 0 -1500 4000 -1500
            LINES
            -3000 -2000 5000 -2000
            5000 -2000 5000 4000
            5000 4000 -3000 4000
            -3000 4000 -3000 -2000
            DATA
            2000 0
            2020 0
            2040 0
            2060 0
            3000 3000
            """;

    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    private World map(String text, RobotToPlace... robots) {
        return WorldReader.read(fixtures.write("lab.map", text), List.of(robots));
    }

    @Test
    void aMapLoadsAsAWorldWithItsOwnCoordinates() {
        World w = map(LAB);
        assertEquals("lab", w.name());
        // lines and points reach from (-3000, -2000) to (5000, 4000); 1 m more on each side
        assertEquals(new Bounds(-4000, -3000, 10000, 8000), w.bounds());
        // four walls, the row of four points as one obstacle, the lone point
        assertEquals(6, w.obstacles().size());
        assertEquals(List.of(12, 13, 14, 15, 17, 21), w.obstacles().stream().map(o -> o.line()).toList());
    }

    @Test
    void aMapLineIsAThinWall() {
        assertArrayEquals(new double[] {-3010, -2010, 5010, -2010, 5010, -1990, -3010, -1990},
                map(LAB).obstacles().get(0).xy());
    }

    @Test
    void forbiddenZonesAreKeptButNotSolid() {
        World w = map(LAB);
        assertEquals(List.of(new ForbiddenZone(true, new double[] {-2500, 2500, -1500, 2500, -1500, 3500, -2500, 3500},
                        "keep out", 9),
                new ForbiddenZone(false, new double[] {0, -1500, 4000, -1500}, "", 10)), w.zones());
        assertTrue(w.obstacles().stream().noneMatch(o -> o.line() == 9 || o.line() == 10));
    }

    @Test
    void withoutRobotsAMapHasOneP3dxAtItsHome() {
        List<RobotSpec> robots = map(LAB).robots();
        assertEquals(1, robots.size());
        RobotSpec r = robots.get(0);
        assertEquals(List.of("p3dx_1", "pioneer", 1000.0, 1000.0, 90.0), List.of(r.name(), r.type(), r.x(), r.y(), r.th()));
        assertEquals("p3dx.p", r.parameterFile().getFileName().toString());
    }

    @Test
    void twoRobotsWithOneHomeStartOneMetreApartAlongMinusY() {
        List<RobotSpec> robots = map(LAB, new RobotToPlace("p3dx", null), new RobotToPlace("p3at", "scout2")).robots();
        assertEquals(List.of("p3dx_1", "scout2"), robots.stream().map(RobotSpec::name).toList());
        assertEquals(List.of(1000.0, 0.0, 90.0), List.of(robots.get(1).x(), robots.get(1).y(), robots.get(1).th()));
        assertEquals("p3at.p", robots.get(1).parameterFile().getFileName().toString());
    }

    @Test
    void eachRobotTakesTheNextHome() {
        String twoHomes = LAB.replace("Cairn: Goal", "Cairn: RobotHome -1000 0 180 \"\" ICON \"Home2\"\nCairn: Goal");
        List<RobotSpec> robots = map(twoHomes, new RobotToPlace("p3dx", null), new RobotToPlace("p3dx", null),
                new RobotToPlace("p3dx", null)).robots();
        assertEquals(List.of("p3dx_1", "p3dx_2", "p3dx_3"), robots.stream().map(RobotSpec::name).toList());
        assertEquals(List.of(-1000.0, 0.0, 180.0), List.of(robots.get(1).x(), robots.get(1).y(), robots.get(1).th()));
        assertEquals(List.of(-1000.0, -1000.0), List.of(robots.get(2).x(), robots.get(2).y()));
    }

    @Test
    void withoutHomesADockIsUsedElseTheOrigin() {
        String dock = LAB.replace("Cairn: RobotHome 1000 1000 90 \"\" ICON \"Home\"", "Cairn: Dock -1000 -1000 45 \"\" ICON \"D\"");
        RobotSpec docked = map(dock).robots().get(0);
        assertEquals(List.of(-1000.0, -1000.0, 45.0), List.of(docked.x(), docked.y(), docked.th()));
        String none = LAB.replace("Cairn: RobotHome 1000 1000 90 \"\" ICON \"Home\"\n", "");
        RobotSpec origin = map(none).robots().get(0);
        assertEquals(List.of(0.0, 0.0, 0.0), List.of(origin.x(), origin.y(), origin.th()));
    }

    @Test
    void aRobotThatWouldStartInAWallIsNamed() {
        // the second robot, 1 m below the home, is clear; the fourth would straddle the bottom wall
        WorldFileException e = assertThrows(WorldFileException.class, () -> map(LAB, new RobotToPlace("p3dx", null),
                new RobotToPlace("p3dx", null), new RobotToPlace("p3dx", null), new RobotToPlace("p3dx", null)));
        assertEquals(0, e.line());
        assertTrue(e.rule().contains("robot 'p3dx_4' at (1000, -2000) overlaps the map's obstacle from line 12"),
                e.getMessage());
    }

    @Test
    void anUnknownRobotTypeIsNamed() {
        WorldFileException e = assertThrows(WorldFileException.class, () -> map(LAB, new RobotToPlace("p9dx", null)));
        assertTrue(e.rule().startsWith("--robot p9dx: robot parameter file 'p9dx' not found"), e.getMessage());
    }

    @Test
    void aMapErrorNamesTheMapFileAndLine() {
        Path file = fixtures.write("bad.map", "2D-Map\nDATA\n1 2 3\n");
        WorldFileException e = assertThrows(WorldFileException.class, () -> WorldReader.read(file));
        assertEquals(file + ":3: '1 2 3' has 3 values but a point of DATA holds x y", e.getMessage());
    }

    @Test
    void aMapElementBringsTheMapIntoAWorldFile() {
        fixtures.write("lab.map", LAB);
        World w = fixtures.read("mapped.xml", """
                <world name="mapped">
                  <map file="lab.map"/>
                  <heat x="3000" y="1000" intensity="10"/>
                  <robot name="r1" type="pioneer" x="-1000" y="0" th="0" params="../robots/p3dx.p"/>
                  <comms range="5000"/>
                </world>
                """);
        assertEquals(new Bounds(-4000, -3000, 10000, 8000), w.bounds());
        assertEquals(6, w.obstacles().size());
        assertEquals(2, w.zones().size());
        assertEquals(List.of("r1"), w.robots().stream().map(RobotSpec::name).toList());
        assertEquals(1, w.heat().size());
        assertEquals(5000, w.comms().maxRange());
    }

    @Test
    void requestedRobotsJoinAWorldFileWithAMapAtTheMapsHomes() {
        fixtures.write("lab.map", LAB);
        Path file = fixtures.write("mapped.xml", """
                <world name="mapped" boundary="true">
                  <map file="lab.map"/>
                  <robot name="r1" type="pioneer" x="-1000" y="0" th="0" params="../robots/p3dx.p"/>
                </world>
                """);
        World w = WorldReader.read(file, List.of(new RobotToPlace("p3at", null)));
        assertEquals(List.of("r1", "p3at_1"), w.robots().stream().map(RobotSpec::name).toList());
        assertEquals(List.of(1000.0, 1000.0), List.of(w.robots().get(1).x(), w.robots().get(1).y()));
        // the boundary walls run along the map's world, not along (0, 0)
        assertArrayEquals(new double[] {-4000, -3000}, java.util.Arrays.copyOf(w.obstacles().get(0).xy(), 2));
    }

    @Test
    void aWorldFileWithSizeAndMapKeepsItsOwnRectangle() {
        fixtures.write("lab.map", LAB);
        WorldFileException e = fixtures.fails("sized.xml", """
                <world name="sized" width="6000" height="6000">
                  <map file="lab.map"/>
                  <robot name="r1" type="pioneer" x="-1000" y="0" th="0" params="../robots/p3dx.p"/>
                </world>
                """, 3, "robot 'r1' at (-1000, 0) is outside the world 6000 x 6000");
        assertFalse(e.getMessage().contains("from ("));
    }

    @Test
    void aBrokenMapInAWorldFileNamesBothFiles() {
        fixtures.write("bad.map", "2D-Map\nLINES\n0 0 zero 5\n");
        WorldFileException e = fixtures.fails("uses-bad.xml", """
                <world name="m">
                  <map file="bad.map"/>
                </world>
                """, 2, "map ", "bad.map:3: coordinate 'zero' is not a number");
        assertTrue(e.getMessage().contains("uses-bad.xml:2: map "), e.getMessage());
    }

    @Test
    void aSecondMapIsRefused() {
        fixtures.write("lab.map", LAB);
        fixtures.fails("two.xml", """
                <world name="m">
                  <map file="lab.map"/>
                  <map file="lab.map"/>
                </world>
                """, 3, "a world has at most one <map>; the first is at line 2");
    }

    @Test
    void aMapHoldsNoCoordinateLargerThanAWorldMay() {
        assertEquals(World.MAX_SIZE, MapReader.MAX_COORDINATE);
    }
}
