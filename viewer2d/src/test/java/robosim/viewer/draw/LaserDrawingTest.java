package robosim.viewer.draw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.RobotParameters;

/**
 * Laser scans in the fixture world (1 px is 5 mm, y flipped). The robot stands at (3000, 600) mm,
 * pixel (600, 280), facing +x; its body covers pixels 560..640 by 242..318. Scans have three
 * readings 90° apart: to the laser's right, straight ahead, and to its left. Sonar is not drawn.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class LaserDrawingTest {
    private final WorldRenderer renderer = new WorldRenderer();

    private BufferedImage render(RobotParameters params, RobotView robot, boolean laser) {
        RenderOptions options = new RenderOptions(Fixtures.WIDTH_PX, false, false).withLaser(laser).withOdometry(false);
        return renderer.render(Fixtures.world(params, List.of()), Fixtures.snapshot(1, robot), options);
    }

    private static RobotView scanning(int... ranges) {
        return Fixtures.robot(3000, 600, 0, 3000, 600, 0, ranges, 90);
    }

    @Test
    void rayAppearsWhereTheScanSaysAndOnlyWhenAsked() {
        // Laser 150 mm ahead of the centre, at (3150, 600) mm = pixel (630, 280).
        RobotParameters params = Fixtures.params(150, 0, 0, 8000);
        RobotView robot = scanning(300, 600, 400);
        BufferedImage on = render(params, robot, true);
        BufferedImage off = render(params, robot, false);
        // Ahead: 600 mm to (3750, 600) mm, pixel (750, 280).
        assertNotEquals(WorldRenderer.BACKGROUND, Pixels.at(on, 700, 280));
        assertEquals(WorldRenderer.BACKGROUND, Pixels.at(off, 700, 280));
        assertEquals(WorldRenderer.BACKGROUND, Pixels.at(on, 770, 280), "nothing past the reading");
        // Right (-y, down in the image): 300 mm to pixel (630, 340); left: 400 mm to pixel (630, 200).
        assertNotEquals(WorldRenderer.BACKGROUND, Pixels.at(on, 630, 330));
        assertNotEquals(WorldRenderer.BACKGROUND, Pixels.at(on, 630, 210));
        // Between the rays the floor shows: they are rays, not a filled fan.
        assertEquals(WorldRenderer.BACKGROUND, Pixels.at(on, 700, 310));
        assertEquals(0, Pixels.differing(on, off, 0, 0, 550, 400), "nothing drawn away from the scan");
    }

    @Test
    void rayEndsInADotWhereTheBeamHitSomething() {
        RobotView robot = scanning(0, 600, 0);
        BufferedImage hit = render(Fixtures.params(150, 0, 0, 8000), robot, true);
        BufferedImage maxRange = render(Fixtures.params(150, 0, 0, 600), robot, true);
        Color dot = Pixels.at(hit, 750, 280);
        Color ray = Pixels.at(hit, 700, 280);
        assertTrue(brightness(dot) < brightness(ray) - 40, "the hit is darker than the ray: " + dot + " vs " + ray);
        assertEquals(ray, Pixels.at(maxRange, 749, 280), "a reading at the laser's range hit nothing");
    }

    @Test
    void scanStartsFromTheLasersMountingPose() {
        // Laser 150 mm behind and 100 mm left of the centre, facing left: at (2850, 700) mm, pixel
        // (570, 260), its right is +x, ahead is +y and its left is -x.
        BufferedImage image = render(Fixtures.params(-150, 100, 90, 8000), scanning(500, 500, 500), true);
        assertNotEquals(WorldRenderer.BACKGROUND, Pixels.at(image, 660, 260), "right of the laser: +x");
        assertNotEquals(WorldRenderer.BACKGROUND, Pixels.at(image, 570, 180), "ahead of the laser: +y");
        assertNotEquals(WorldRenderer.BACKGROUND, Pixels.at(image, 490, 260), "left of the laser: -x");
        assertEquals(WorldRenderer.BACKGROUND, Pixels.at(image, 700, 280), "nothing along the robot's own heading");
    }

    @Test
    void scanIsDrawnFromTheTruePoseNotTheOdometry() {
        // The robot believes it is at (1000, 1500) mm facing -x; the scan is of where it really is.
        RobotView robot = Fixtures.robot(3000, 600, 0, 1000, 1500, 180, new int[] {0, 600, 0}, 90);
        BufferedImage image = render(Fixtures.params(150, 0, 0, 8000), robot, true);
        assertNotEquals(WorldRenderer.BACKGROUND, Pixels.at(image, 700, 280));
        assertEquals(WorldRenderer.BACKGROUND, Pixels.at(image, 120, 100));
    }

    @Test
    void emptyScanDrawsNothing() {
        RobotView robot = scanning();
        RobotParameters params = Fixtures.params(150, 0, 0, 8000);
        // the world only: the legend below it names the laser scan when scans are shown
        assertEquals(0, Pixels.differing(render(params, robot, true), render(params, robot, false), 0, 0, 800, 400));
    }

    private static int brightness(Color c) {
        return (c.getRed() + c.getGreen() + c.getBlue()) / 3;
    }
}
