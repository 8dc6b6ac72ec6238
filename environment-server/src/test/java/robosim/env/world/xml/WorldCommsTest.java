package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.comms.CommsSettings;
import robosim.env.world.World;
import robosim.env.world.Obstacle;
import robosim.env.world.Noise;
import robosim.env.world.RobotSpec;

/** The communications settings as a valid world file gives them. */
class WorldCommsTest {
    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    @Test
    void commsIsRead() {
        World world = fixtures.read("talk.xml", """
                <world name="talk" width="8000" height="8000">
                  <comms range="8000" wallsBlock="true" latency="3" loss="0.05" maxBytes="1024"/>
                </world>
                """);
        assertEquals(new CommsSettings(8000, true, 3, 0.05, 1024), world.comms());
    }

    @Test
    void worldWithoutCommsHasTheDefaults() {
        World world = fixtures.read("plain.xml", """
                <world name="plain" width="6000" height="6000">
                  <wall x1="0" y1="3000" x2="1000" y2="3000"/>
                </world>
                """);
        assertEquals(CommsSettings.DEFAULT, world.comms());
    }

    @Test
    void emptyCommsElementHasTheDefaults() {
        World world = fixtures.read("empty.xml", """
                <world name="empty" width="6000" height="6000">
                  <comms/>
                </world>
                """);
        assertEquals(new CommsSettings(0, false, 1, 0, 65536), world.comms());
    }

    @Test
    void missingCommsAttributesTakeTheirDefaults() {
        World world = fixtures.read("walls.xml", """
                <world name="walls" width="6000" height="6000">
                  <comms wallsBlock="true" loss="0.5"/>
                </world>
                """);
        assertEquals(new CommsSettings(0, true, 1, 0.5, 65536), world.comms());
    }

    @Test
    void limitsOfEachRuleAreAllowed() {
        World world = fixtures.read("edges.xml", """
                <world name="edges" width="6000" height="6000">
                  <comms range="0" wallsBlock="false" latency="1" loss="1" maxBytes="1"/>
                </world>
                """);
        assertEquals(new CommsSettings(0, false, 1, 1, 1), world.comms());
    }

    @Test
    void commsAmongOtherElementsKeepsThemAll() {
        World world = fixtures.read("mixed.xml", """
                <world name="mixed" width="6000" height="6000">
                  <wall x1="0" y1="3000" x2="1000" y2="3000"/>
                  <comms latency="2"/>
                  <robot name="r1" type="pioneer" x="500" y="500" params="../robots/p3dx.p"/>
                  <noise sonar="5"/>
                  <heat x="4000" y="1000" intensity="20"/>
                </world>
                """);
        assertEquals(2, world.comms().latencySteps());
        assertEquals(List.of(2), world.obstacles().stream().map(Obstacle::line).toList());
        assertEquals(List.of(4), world.robots().stream().map(RobotSpec::line).toList());
        assertEquals(new Noise(5, 0, 0), world.noise());
        assertEquals(1, world.heat().size());
    }

    @Test
    void negativeZeroRangeAndLossReadAsZero() {
        World world = fixtures.read("zero.xml", """
                <world name="zero" width="6000" height="6000">
                  <comms range="-0" loss="-0"/>
                </world>
                """);
        assertEquals(CommsSettings.DEFAULT, world.comms());
    }

    @Test
    void worldsBuiltWithoutCommsHaveTheDefaults() {
        Path source = Path.of("w.xml");
        assertEquals(CommsSettings.DEFAULT, new World("w", source, 1000, 1000, 100, List.of(), List.of()).comms());
        assertEquals(CommsSettings.DEFAULT,
                new World("w", source, 1000, 1000, 100, List.of(), List.of(), List.of(), Noise.NONE).comms());
    }
}
