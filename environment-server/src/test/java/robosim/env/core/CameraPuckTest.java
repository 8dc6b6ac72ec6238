package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.env.world.WorldObject;
import robosim.protocol.CameraView;
import robosim.protocol.ColorBlob;
import robosim.protocol.Command;
import robosim.protocol.PtzModel;

/**
 * The camera sees the world's pucks in their colours: a robot at (1000, 5000) facing +x, its lens
 * 300 mm up at its centre and tilted down, and a puck 1000 mm ahead.
 */
class CameraPuckTest {
    private static CameraView look(String color, double puckY) {
        var world = Worlds.world(10000, 10000, List.of(), Worlds.robot("r", 1000, 5000, 0))
                .withObjects(List.of(new WorldObject(WorldObject.PUCK, 2000, puckY, 38, color, 1)));
        Simulation sim = new Simulation(world);
        sim.step(Map.of("r", List.of(new Command.ConfigurePtz(PtzModel.VCC4, 300), new Command.TrackColors(true),
                new Command.AimPtz(0, -20, 0))));
        for (int i = 0; i < 10; i++) {
            sim.step(Map.of());
        }
        return sim.state("r").get(CameraView.PART);
    }

    private static List<ColorBlob> red(CameraView view) {
        return view.blobs().stream().filter(b -> b.channel() == 1).toList();
    }

    @Test
    void aRedPuckAheadIsOneRedBlobInTheMiddleColumns() {
        List<ColorBlob> blobs = red(look("red", 5000));

        assertEquals(1, blobs.size(), "one red blob: " + blobs);
        ColorBlob b = blobs.get(0);
        assertEquals(80, b.xcg(), 2, "centred across");
        // a 76 mm puck 1000 mm away spans about 2 · atan(38 / 1000) = 4.4° of the VC-C4's 45°: ~16 columns
        int width = b.right() - b.left() + 1;
        assertTrue(width >= 12 && width <= 20, "about 16 columns wide: " + width);
    }

    @Test
    void aPuckToTheLeftAppearsLeftOfTheCentre() {
        List<ColorBlob> blobs = red(look("red", 5200));

        assertEquals(1, blobs.size());
        assertTrue(blobs.get(0).xcg() < 70, "left of the centre: " + blobs.get(0).xcg());
    }

    @Test
    void aPuckWithoutAColourBelongsToNoChannel() {
        assertTrue(look(null, 5000).blobs().isEmpty());
    }
}
