package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.locationtech.jts.algorithm.Orientation;
import org.locationtech.jts.geom.Envelope;
import robosim.comms.CommsSettings;
import robosim.geometry.GeometryClient;
import robosim.env.world.World;
import robosim.env.world.Obstacle;
import robosim.env.world.HeatSource;
import robosim.env.world.Noise;
import robosim.env.world.RobotSpec;

class WorldReaderTest {
    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    @ParameterizedTest
    @CsvSource({
        "empty-room.xml,     empty-room,     6000,  6000,  4,  'r1,r2'",
        "small-maze.xml,     small-maze,     8000,  8000,  10, 'r1,r2'",
        "cluttered-room.xml, cluttered-room, 10000, 10000, 16, 'r1,r2,r3'"})
    void shippedWorldLoads(String file, String name, double width, double height, int obstacles, String robots) {
        World world = WorldReader.read(WorldFixtures.root().resolve("testLoadFiles/environment").resolve(file));
        assertEquals(name, world.name());
        assertEquals(width, world.width());
        assertEquals(height, world.height());
        assertEquals(100, world.stepMs());
        assertEquals(obstacles, world.obstacles().size());
        assertEquals(List.of(robots.split(",")), world.robots().stream().map(RobotSpec::name).toList());
        for (RobotSpec r : world.robots()) {
            assertTrue(Files.isRegularFile(r.parameterFile()), r.parameterFile()::toString);
        }
    }

    @Test
    void clutteredRoomR3IsAP3at() {
        World world = WorldReader.read(WorldFixtures.root().resolve("testLoadFiles/environment/cluttered-room.xml"));
        assertEquals("p3at", world.robots().get(2).parameters().subclass());
        assertEquals("p3dx", world.robots().get(0).parameters().subclass());
    }

    @Test
    void exampleInTheFormatDocumentLoads() throws IOException {
        String doc = Files.readString(WorldFixtures.root().resolve("docs/WORLD-FORMAT.md"));
        int start = doc.indexOf("```xml\n") + "```xml\n".length();
        World world = fixtures.read("example.xml", doc.substring(start, doc.indexOf("```", start)));
        assertEquals("small-maze", world.name());
        assertEquals(6, world.obstacles().size());
        assertEquals(2, world.robots().size());
        assertEquals(List.of(new HeatSource(4500, 5000, 40, 11)), world.heat());
        assertEquals(new Noise(5, 10, 0.0075), world.noise());
        assertEquals(new CommsSettings(8000, true, 1, 0.05, 65536), world.comms());
        assertEquals(java.util.Map.of("cellSize", "2000"), world.properties());
    }

    @Test
    void interleavedElementsAreAllKeptInFileOrder() {
        World world = fixtures.read("mixed.xml", """
                <world name="mixed" width="6000" height="6000">
                  <wall x1="0" y1="3000" x2="1000" y2="3000"/>
                  <robot name="r1" type="pioneer" x="500" y="500" params="../robots/p3dx.p"/>
                  <polygon points="2000,2000 2600,2000 2600,2600"/>
                  <wall x1="0" y1="4000" x2="1000" y2="4000"/>
                  <robot name="r2" type="pioneer" x="5000" y="500" params="../robots/p3dx.p"/>
                  <polygon points="4000,4000 4600,4000 4600,4600"/>
                  <wall x1="0" y1="5000" x2="1000" y2="5000"/>
                </world>
                """);
        assertEquals(List.of(2, 4, 5, 7, 8), world.obstacles().stream().map(Obstacle::line).toList());
        assertEquals(List.of("r1", "r2"), world.robots().stream().map(RobotSpec::name).toList());
        assertEquals(List.of(3, 6), world.robots().stream().map(RobotSpec::line).toList());
    }

    @Test
    void lineIsTheElementsOwnFirstLine() {
        World world = fixtures.read("lines.xml", """
                <?xml version="1.0"?>
                <!-- a comment
                     over two lines -->
                <world name="lines" width="6000" height="6000">

                  <polygon
                      points="2000,2000 2600,2000 2600,2600"
                      height="400"/>
                  <wall x1="0" y1="3000" x2="1000" y2="3000">
                  </wall>
                  <robot name="r1"
                         type="pioneer" x="500" y="500"
                         params="../robots/p3dx.p"/>
                  <wall x1="0" y1="5000" x2="1000" y2="5000"></wall>
                </world>
                """);
        assertEquals(List.of(6, 9, 14), world.obstacles().stream().map(Obstacle::line).toList());
        assertEquals(11, world.robots().get(0).line());
    }

    @Test
    void defaultsApplyWhenAttributesAreLeftOut() {
        World world = fixtures.read("defaults.xml", """
                <world name="defaults" width="6000" height="5000">
                  <wall x1="1000" y1="1000" x2="2000" y2="1000"/>
                  <robot name="r1" type="pioneer" x="500" y="500" params="../robots/p3dx.p"/>
                </world>
                """);
        assertEquals(WorldReader.DEFAULT_STEP_MS, world.stepMs());
        assertEquals(500, world.obstacles().get(0).height());
        assertEquals(0, world.robots().get(0).th());
        assertEquals(100, GeometryClient.polygon(world.obstacles().get(0).xy()).getEnvelopeInternal().getHeight());
    }

    @Test
    void wallBecomesARectangleWithSquareCaps() {
        World world = fixtures.read("wall.xml", """
                <world name="wall" width="6000" height="6000">
                  <wall x1="1000" y1="2000" x2="3000" y2="2000" thickness="200" height="300"/>
                </world>
                """);
        Obstacle wall = world.obstacles().get(0);
        assertArrayEquals(new double[] {900, 1900, 3100, 1900, 3100, 2100, 900, 2100}, wall.xy(), 1e-9);
        assertEquals(300, wall.height());
        assertEquals(2, wall.line());
    }

    @Test
    void clockwisePolygonIsTurnedCounterClockwise() {
        World world = fixtures.read("cw.xml", """
                <world name="cw" width="6000" height="6000">
                  <polygon points="0,0 0,1000 1000,1000 1000,0 0,0"/>
                </world>
                """);
        double[] xy = world.obstacles().get(0).xy();
        assertEquals(8, xy.length, "the closing point is dropped");
        assertTrue(Orientation.isCCW(GeometryClient.polygon(xy).getCoordinates()));
        assertEquals(1_000_000, GeometryClient.polygon(xy).getArea(), 1e-9);
    }

    @Test
    void boundaryAddsFourWallsJustInsideTheEdges() {
        World world = fixtures.read("boundary.xml", """
                <world name="boundary" width="6000" height="4000" boundary="true">
                </world>
                """);
        assertEquals(4, world.obstacles().size());
        Envelope all = new Envelope();
        for (Obstacle wall : world.obstacles()) {
            Envelope env = wall.polygon().getEnvelopeInternal();
            assertEquals(100, Math.min(env.getWidth(), env.getHeight()), 1e-9);
            assertEquals(1, wall.line());
            all.expandToInclude(env);
        }
        assertEquals(new Envelope(0, 6000, 0, 4000), all);
    }

    @Test
    void parameterFileIsResolvedAgainstTheWorldFile() {
        World world = fixtures.read("params.xml", """
                <world name="params" width="6000" height="6000">
                  <robot name="r1" type="pioneer" x="1000" y="1000" th="90" params="../robots/p3at.p"/>
                </world>
                """);
        RobotSpec r1 = world.robots().get(0);
        assertEquals(dir.resolve("robots/p3at.p").toAbsolutePath().normalize(), r1.parameterFile());
        assertEquals(505, r1.parameters().robotWidth());
        assertEquals(Math.PI / 2, r1.pose().th(), 1e-12);
        assertEquals(4, r1.body().size());
    }

    @Test
    void recordsDoNotShareTheirArraysOrLists() {
        World world = fixtures.read("copy.xml", """
                <world name="copy" width="6000" height="6000">
                  <polygon points="0,0 1000,0 0,1000"/>
                </world>
                """);
        world.obstacles().get(0).xy()[0] = 99;
        assertEquals(0, world.obstacles().get(0).xy()[0]);
        assertEquals(world.obstacles().get(0), new Obstacle(new double[] {0, 0, 1000, 0, 0, 1000}, 500, 2));
    }
}
