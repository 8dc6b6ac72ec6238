package robosim.viewer.view3d;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription;
import robosim.protocol.WorldDescription.Obstacle;
import robosim.protocol.WorldDescription.RobotInfo;
import robosim.protocol.RobotParameters;
import robosim.viewer.draw.RobotPalette;
import robosim.viewer.draw.WorldRenderer;
import robosim.viewer.draw.Pixels;

/**
 * The 3D view of a literal world: a 4000 x 2000 mm floor, a 500 mm block from (1000, 500) to
 * (1500, 1000) and a wall 100 mm thick along y = 1000 from x = 2000 to 3800 (y 950 to 1050), of a
 * height each test chooses; robot r1, 400 x 400 mm. Pixels are read where the projection says a
 * face lies, at least a few pixels inside it.
 */
class SolidRendererTest {
    private static final double[] UP = {0, 0, 1};
    private static final int WIDTH = 800;

    private static WorldDescription world(double wallHeight) {
        RobotParameters body = new RobotParameters("Pioneer", "test", 290, 400, 200, 200, 1000, 300, 300, 300,
                100, 100, 0.006, 5000, List.of());
        return new WorldDescription("solid", 4000, 2000, 100, List.of(
                new Obstacle(new double[] {1000, 500, 1500, 500, 1500, 1000, 1000, 1000}, 500),
                new Obstacle(new double[] {2000, 950, 3800, 950, 3800, 1050, 2000, 1050}, wallHeight)),
                List.of(new RobotInfo("r1", "pioneer", body)));
    }

    private static Snapshot robotAt(double x, double y) {
        return new Snapshot(7, 700, List.of(new RobotView("r1", x, y, 0, false, true, new int[0])));
    }

    /** The colour of the pixel where the projection puts a world point. */
    private static Color at(BufferedImage image, Projection p, double x, double y, double z) {
        return new Color(image.getRGB((int) Math.round(p.px(x, y, z)), (int) Math.round(p.py(x, y, z))));
    }

    private static Projection projection(WorldDescription world, Camera camera) {
        return Projection.fit(world, camera, WIDTH, Projection.heightFor(world, camera, WIDTH), Double.NaN, Double.NaN);
    }

    private static BufferedImage render(WorldDescription world, Snapshot snapshot, Camera camera, Light light) {
        return SolidRenderer.render(world, snapshot, new SceneOptions(WIDTH, camera, light, false, false, false), null);
    }

    @Test
    void fromStraightAboveTheRoofsLieWhereTheMapPutsThem() {
        WorldDescription world = world(300);
        Camera above = new Camera(-90, 90, 1);
        Light light = new Light(0, 90);
        BufferedImage image = render(world, null, above, light);
        Projection p = projection(world, above);
        Color roof = Shading.shade(SceneBuilder.WALL, UP, light.towardsLight());
        Color floor = Shading.shade(WorldRenderer.BACKGROUND, UP, light.towardsLight());
        assertEquals(roof, at(image, p, 1250, 750, 500), "the block's roof");
        assertEquals(roof, at(image, p, 2900, 1000, 300), "the wall's roof");
        assertEquals(floor, at(image, p, 2900, 1500, 0), "the floor north of the wall");
        assertEquals(floor, at(image, p, 600, 750, 0), "the floor west of the block");
        assertTrue(p.px(1000, 750, 0) < p.px(1500, 750, 0) && p.py(1250, 500, 0) > p.py(1250, 1000, 0),
                "x grows right and y grows up, as on the 2D map");
    }

    @Test
    void facesTurnedFromTheLightAreDarkerThanFacesTurnedToIt() {
        WorldDescription world = world(300);
        Camera southEast = new Camera(-45, 30, 1);
        Light east = new Light(0, 0);
        BufferedImage image = render(world, null, southEast, east);
        Projection p = projection(world, southEast);
        Color eastFace = at(image, p, 1500, 750, 250);
        Color southFace = at(image, p, 1250, 500, 250);
        assertEquals(Shading.shade(SceneBuilder.WALL, new double[] {1, 0, 0}, east.towardsLight()), eastFace);
        assertEquals(Shading.shade(SceneBuilder.WALL, new double[] {0, -1, 0}, east.towardsLight()), southFace);
        assertTrue(brightness(eastFace) > brightness(southFace) + 100,
                "lit " + eastFace + " vs turned away " + southFace);
        assertEquals(SceneBuilder.WALL, eastFace, "a face square to the light gets all of it");
    }

    @Test
    void wallsRiseToTheirOwnHeight() {
        Camera south = new Camera(-90, 30, 1);
        Light light = Light.DEFAULT;
        Color face = Shading.shade(SceneBuilder.WALL, new double[] {0, -1, 0}, light.towardsLight());
        Color roof = Shading.shade(SceneBuilder.WALL, UP, light.towardsLight());
        Color floor = Shading.shade(WorldRenderer.BACKGROUND, UP, light.towardsLight());
        WorldDescription low = world(300);
        BufferedImage lowImage = render(low, null, south, light);
        Projection lp = projection(low, south);
        assertEquals(face, at(lowImage, lp, 2900, 950, 150), "half way up the 300 mm wall's south face");
        assertEquals(roof, at(lowImage, lp, 2900, 1000, 300), "on its roof");
        assertEquals(floor, at(lowImage, lp, 2900, 950, 500), "above it: the floor behind");
        WorldDescription high = world(900);
        BufferedImage highImage = render(high, null, south, light);
        Projection hp = projection(high, south);
        assertEquals(face, at(highImage, hp, 2900, 950, 500), "a 900 mm wall covers what a 300 mm one does not");
        assertEquals(roof, at(highImage, hp, 2900, 1000, 900));
    }

    @Test
    void aRobotBehindATallWallIsHiddenAndOneInFrontIsDrawnOverIt() {
        WorldDescription world = world(900);
        Camera south = new Camera(-90, 20, 1);
        Light light = Light.DEFAULT;
        Color robotRoof = Shading.shade(RobotPalette.colour(0), UP, light.towardsLight());
        Color wallFace = Shading.shade(SceneBuilder.WALL, new double[] {0, -1, 0}, light.towardsLight());
        Projection p = projection(world, south);
        BufferedImage behind = render(world, robotAt(2400, 1500), south, light);
        assertEquals(wallFace, at(behind, p, 2300, 1500, Projection.ROBOT_HEIGHT_MM), "hidden behind the wall");
        BufferedImage inFront = render(world, robotAt(2400, 600), south, light);
        assertEquals(robotRoof, at(inFront, p, 2300, 600, Projection.ROBOT_HEIGHT_MM), "its roof, over the wall");
        assertNotEquals(robotRoof, at(behind, p, 2300, 1500, Projection.ROBOT_HEIGHT_MM));
    }

    @Test
    void theImageIsAsWideAsAskedAndTheCaptionIsDrawn() {
        WorldDescription world = world(300);
        BufferedImage plain = SolidRenderer.render(world, robotAt(3000, 1500),
                SceneOptions.of(640).showing(false, false, false).withKey(false), null);
        BufferedImage captioned = SolidRenderer.render(world, robotAt(3000, 1500), SceneOptions.of(640), null);
        assertEquals(640, plain.getWidth());
        assertEquals(Projection.heightFor(world, Camera.DEFAULT, 640), plain.getHeight());
        assertEquals(new Color(SolidRenderer.SKY.getRGB()), new Color(plain.getRGB(5, 5)), "sky in the corner");
        assertNotEquals(plain.getRGB(12, 12), captioned.getRGB(12, 12), "the caption box covers the corner");
    }

    @Test
    void badCameraAndLightValuesAreNamedWithTheRule() {
        assertEquals("2.0 was supplied for elevation: it must be from 5.0 to 90 degrees",
                assertThrows(IllegalArgumentException.class, () -> new Camera(0, 2, 1)).getMessage());
        assertEquals("0.0 was supplied for zoom: it must be from 0.1 to 50.0",
                assertThrows(IllegalArgumentException.class, () -> new Camera(0, 45, 0)).getMessage());
        assertEquals("95.0 was supplied for the light's elevation: it must be from 0 to 90 degrees",
                assertThrows(IllegalArgumentException.class, () -> new Light(0, 95)).getMessage());
        assertEquals(180.0, new Camera(-180, 45, 1).azimuth());
        assertEquals(-90.0, new Camera(270, 45, 1).azimuth());
    }

    private static int brightness(Color c) {
        return c.getRed() + c.getGreen() + c.getBlue();
    }
}
