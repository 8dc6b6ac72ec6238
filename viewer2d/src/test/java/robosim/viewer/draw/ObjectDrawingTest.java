package robosim.viewer.draw;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;

/**
 * Pucks in the fixture world (1 px is 5 mm, y flipped): one starting at (2000, 1500) mm is pixel
 * (400, 100), 15 px across.
 */
class ObjectDrawingTest {
    private final WorldRenderer renderer = new WorldRenderer();
    private final WorldDescription world = Fixtures.world().withObjects(
            List.of(new WorldDescription.WorldObject("puck", 2000, 1500, 38, "red")));

    private BufferedImage render(Snapshot snapshot) {
        return renderer.render(world, snapshot, RenderOptions.of(Fixtures.WIDTH_PX));
    }

    @Test
    void withoutASnapshotAPuckIsDrawnWhereItStartsInItsColour() {
        assertEquals(ObjectPainter.colour("red"), Pixels.at(render(null), 400, 100));
    }

    @Test
    void aSnapshotMovesIt() {
        Snapshot moved = Fixtures.snapshot(5, Fixtures.robotAtRest())
                .withObjects(List.of(new Snapshot.ObjectView(2500, 1500, null, false)));
        BufferedImage image = render(moved);
        assertEquals(ObjectPainter.colour("red"), Pixels.at(image, 500, 100));
        assertEquals(WorldRenderer.BACKGROUND, Pixels.at(image, 400, 100));
    }

    @Test
    void aSnapshotFromBeforeObjectsLeavesItWhereItStarts() {
        BufferedImage image = render(Fixtures.snapshot(5, Fixtures.robotAtRest()));
        assertEquals(ObjectPainter.colour("red"), Pixels.at(image, 400, 100));
    }

    @Test
    void aLiftedPuckHasAWhiteRim() {
        Snapshot lifted = Fixtures.snapshot(5, Fixtures.robotAtRest())
                .withObjects(List.of(new Snapshot.ObjectView(2000, 1500, "r1", true)));
        BufferedImage image = render(lifted);
        assertEquals(ObjectPainter.colour("red"), Pixels.at(image, 400, 100));
        // the white rim 2 px inside the 15 px disc's edge, on its left: lighter than the red fill
        assertEquals(true, greenest(image) > 120, "the greenest pixel left of the centre has " + greenest(image));
        BufferedImage onTheFloor = render(Fixtures.snapshot(5, Fixtures.robotAtRest())
                .withObjects(List.of(new Snapshot.ObjectView(2000, 1500, "r1", false))));
        assertEquals(true, greenest(onTheFloor) < 60, "no rim: " + greenest(onTheFloor));
    }

    /** @return the most green of the pixels inside the disc's dark rim, left of its centre */
    private static int greenest(BufferedImage image) {
        int g = 0;
        for (int x = 394; x < 400; x++) {
            g = Math.max(g, Pixels.at(image, x, 100).getGreen());
        }
        return g;
    }

    @Test
    void coloursAreNamesOrHex() {
        assertEquals(new Color(0x12ab34), ObjectPainter.colour("#12ab34"));
        assertEquals(ObjectPainter.DEFAULT, ObjectPainter.colour(null));
        assertEquals(ObjectPainter.DEFAULT, ObjectPainter.colour("chartreuse"));
    }
}
