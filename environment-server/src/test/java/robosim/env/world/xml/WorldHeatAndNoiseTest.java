package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.world.World;
import robosim.env.world.Obstacle;
import robosim.env.world.HeatSource;
import robosim.env.world.Noise;
import robosim.env.world.RobotSpec;

/** Heat sources and noise as a valid world file gives them. */
class WorldHeatAndNoiseTest {
    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    @Test
    void heatAndNoiseAreRead() {
        World world = fixtures.read("gold.xml", """
                <world name="gold" width="8000" height="8000">
                  <noise sonar="5" laser="10" odometry="0.0075"/>
                  <heat x="7000" y="3000" intensity="40"/>
                </world>
                """);
        assertEquals(List.of(new HeatSource(7000, 3000, 40, 3)), world.heat());
        assertEquals(new Noise(5, 10, 0.0075), world.noise());
    }

    @Test
    void worldWithoutHeatOrNoiseHasNone() {
        World world = fixtures.read("plain.xml", """
                <world name="plain" width="6000" height="6000">
                  <wall x1="0" y1="3000" x2="1000" y2="3000"/>
                </world>
                """);
        assertEquals(List.of(), world.heat());
        assertEquals(Noise.NONE, world.noise());
    }

    @Test
    void noiseAttributesDefaultToZero() {
        World world = fixtures.read("laser.xml", """
                <world name="laser" width="6000" height="6000">
                  <noise laser="12.5"/>
                </world>
                """);
        assertEquals(new Noise(0, 12.5, 0), world.noise());
    }

    @Test
    void emptyNoiseElementIsNoNoise() {
        World world = fixtures.read("quiet.xml", """
                <world name="quiet" width="6000" height="6000">
                  <noise/>
                </world>
                """);
        assertEquals(Noise.NONE, world.noise());
    }

    @Test
    void heatInterleavedWithOtherElementsIsAllKeptInFileOrder() {
        World world = fixtures.read("mixed.xml", """
                <world name="mixed" width="6000" height="6000">
                  <heat x="5000" y="5000" intensity="10"/>
                  <wall x1="0" y1="3000" x2="1000" y2="3000"/>
                  <robot name="r1" type="pioneer" x="500" y="500" params="../robots/p3dx.p"/>
                  <heat x="4000" y="1000" intensity="20"/>
                  <polygon points="2000,2000 2600,2000 2600,2600"/>
                  <noise odometry="0.01"/>
                  <robot name="r2" type="pioneer" x="5000" y="500" params="../robots/p3dx.p"/>
                  <heat x="3000" y="3000" intensity="30.5"/>
                </world>
                """);
        assertEquals(List.of(new HeatSource(5000, 5000, 10, 2), new HeatSource(4000, 1000, 20, 5),
                new HeatSource(3000, 3000, 30.5, 9)), world.heat());
        assertEquals(List.of(3, 6), world.obstacles().stream().map(Obstacle::line).toList());
        assertEquals(List.of(4, 8), world.robots().stream().map(RobotSpec::line).toList());
        assertEquals(new Noise(0, 0, 0.01), world.noise());
    }

    @Test
    void heatOnTheWorldsEdgeOrAnObstaclesEdgeIsAllowed() {
        World world = fixtures.read("edges.xml", """
                <world name="edges" width="6000" height="6000">
                  <polygon points="2000,2000 2600,2000 2600,2600 2000,2600"/>
                  <heat x="0" y="6000" intensity="1"/>
                  <heat x="2000" y="2300" intensity="1"/>
                </world>
                """);
        assertEquals(2, world.heat().size());
    }

    @Test
    void negativeZeroNoiseReadsAsZero() {
        World world = fixtures.read("zero.xml", """
                <world name="zero" width="6000" height="6000">
                  <noise sonar="-0"/>
                </world>
                """);
        assertEquals(Noise.NONE, world.noise());
    }
}
