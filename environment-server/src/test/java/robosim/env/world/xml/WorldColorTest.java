package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.nio.file.Path;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.world.World;

/** The {@code color} attribute of walls and polygons, which the robots' cameras see. */
class WorldColorTest {
    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    @Test
    void wallsAndPolygonsTakeANamedOrHexColourAndAHeight() {
        World w = fixtures.read("colors.xml", """
                <world name="colors" width="6000" height="6000">
                  <wall x1="1000" y1="1000" x2="2000" y2="1000" color="Red"/>
                  <polygon points="3000,3000 3500,3000 3000,3500" height="150" color="#00A0ff"/>
                  <polygon points="4000,4000 4500,4000 4000,4500"/>
                </world>
                """);
        int n = w.obstacles().size();
        assertEquals("#ff0000", w.obstacles().get(n - 3).color());
        assertEquals("#00a0ff", w.obstacles().get(n - 2).color());
        assertEquals(150, w.obstacles().get(n - 2).height());
        assertNull(w.obstacles().get(n - 1).color(), "no colour: occludes, tracked by no channel");
    }

    @Test
    void aBadColourIsRefusedNamingTheFileLineAndValue() {
        fixtures.fails("badcolor.xml", """
                <world name="badcolor" width="6000" height="6000">
                  <polygon points="3000,3000 3500,3000 3000,3500" color="reddish"/>
                </world>
                """, 2, "attribute color on <polygon> is 'reddish', not a colour: give #rrggbb or one of");
        fixtures.fails("badhex.xml", """
                <world name="badhex" width="6000" height="6000">

                  <wall x1="1000" y1="1000" x2="2000" y2="1000" color="#12345"/>
                </world>
                """, 3, "attribute color on <wall> is '#12345'");
    }

    @Test
    void theShippedColourRoomHasARedAndABlueBox() {
        World w = WorldReader.read(WorldFixtures.root().resolve("testLoadFiles/environment/color-room.xml"));
        java.util.List<String> colors = w.obstacles().stream().map(robosim.env.world.Obstacle::color)
                .filter(java.util.Objects::nonNull).toList();
        assertEquals(java.util.List.of("#ff0000", "#0000ff"), colors);
    }
}
