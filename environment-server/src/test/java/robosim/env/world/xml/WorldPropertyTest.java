package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import robosim.env.world.RunRules;
import robosim.env.world.World;

/** A world's properties, as a valid world file gives them to robot programs. */
class WorldPropertyTest {
    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    @Test
    void propertiesAreReadInFileOrderAmongOtherElements() {
        World world = fixtures.read("maze.xml", """
                <world name="maze" width="8000" height="8000">
                  <property name="cellSize" value="1000"/>
                  <wall x1="0" y1="3000" x2="2000" y2="3000"/>
                  <property name="goal.kind" value="gold bar"/>
                  <property name="A_b-1" value=""/>
                </world>
                """);

        assertEquals(Map.of("cellSize", "1000", "goal.kind", "gold bar", "A_b-1", ""), world.properties());
        assertEquals(List.of("cellSize", "goal.kind", "A_b-1"), List.copyOf(world.properties().keySet()));
    }

    @Test
    void aWorldWithoutPropertiesHasNone() {
        World world = fixtures.read("plain.xml", """
                <world name="plain" width="6000" height="6000"/>
                """);

        assertEquals(Map.of(), world.properties());
    }

    @Test
    void theWorldsOtherFormsKeepTheProperties() {
        World world = fixtures.read("team.xml", """
                <world name="team" width="8000" height="8000">
                  <property name="cellSize" value="1000"/>
                  <robot name="r1" type="pioneer" x="1000" y="1000" th="0" params="../robots/p3dx.p"/>
                  <robot name="r2" type="pioneer" x="3000" y="1000" th="0" params="../robots/p3dx.p"/>
                </world>
                """);
        Map<String, String> cell = Map.of("cellSize", "1000");

        assertEquals(cell, world.withFirstRobots(1).properties());
        assertEquals(cell, world.withRobots(world.robots()).properties());
        assertEquals(cell, world.withRules(RunRules.DEFAULT).properties());
        assertEquals(cell, world.withObjects(List.of()).properties());
        assertEquals(Map.of("x", "1"), world.withProperties(Map.of("x", "1")).properties());
    }

    @Test
    void thePropertiesCannotBeChanged() {
        World world = fixtures.read("maze.xml", """
                <world name="maze" width="8000" height="8000">
                  <property name="cellSize" value="1000"/>
                </world>
                """);

        assertThrows(UnsupportedOperationException.class, () -> world.properties().put("cellSize", "2"));
    }

    @ParameterizedTest
    @CsvSource({"small-maze.xml, 2000", "maze-small.xml, 1500", "maze-medium.xml, 1500", "maze-large.xml, 1500"})
    void theShippedMazesGiveTheirCellSize(String file, String cellSize) {
        World world = WorldReader.read(WorldFixtures.root().resolve("testLoadFiles/environment").resolve(file));

        assertEquals(Map.of("cellSize", cellSize), world.properties());
    }

    @Test
    void anAriaMapHasNoProperties() {
        World world = WorldReader.read(fixtures.write("lab.map", MapWorldTest.LAB));

        assertEquals(Map.of(), world.properties());
    }
}
