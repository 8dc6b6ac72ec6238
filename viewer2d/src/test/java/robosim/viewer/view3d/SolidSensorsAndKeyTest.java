package robosim.viewer.view3d;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.RobotParameters;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.SonarUnit;
import robosim.protocol.WorldDescription;
import robosim.protocol.WorldDescription.Obstacle;
import robosim.protocol.WorldDescription.RobotInfo;
import robosim.viewer.draw.RenderOptions;
import robosim.viewer.draw.WorldRenderer;

/**
 * The 3D view's legend, its sonar and laser switches, the world's colours and robots gone from the
 * run, seen from straight above (so a point of the floor lands where the projection says) in a
 * 4000 x 2000 mm world with a red block from (1000, 500) to (1500, 1000) and robot r1 at
 * (3000, 1500), whose one sonar looks along +x.
 */
class SolidSensorsAndKeyTest {
    private static final int WIDTH = 800;
    private static final double[] UP = {0, 0, 1};
    private static final Camera ABOVE = new Camera(-90, 90, 1);
    private static final Light LIGHT = new Light(0, 90);

    private static WorldDescription world() {
        RobotParameters body = new RobotParameters("Pioneer", "test", 250, 380, 200, 200, 1000, 300, 300, 300, 100,
                100, 0.006, 5000, List.of(new SonarUnit(0, 200, 0, 0)), 150, 0, 0, 8000);
        return new WorldDescription("solid", 4000, 2000, 100, List.of(
                new Obstacle(new double[] {1000, 500, 1500, 500, 1500, 1000, 1000, 1000}, 500, "red")),
                List.of(new RobotInfo("r1", "pioneer", body)));
    }

    private static Snapshot snapshot(boolean connected, Snapshot.Event... events) {
        // the sonar reads 800 mm ahead; the laser's middle reading (straight ahead) 600 mm
        int[] laser = new int[181];
        laser[90] = 600;
        RobotView r1 = new RobotView("r1", 3000, 1500, 0, false, connected, new int[] {800}, 3000, 1500, 0, laser, 1);
        return new Snapshot(7, 700, List.of(r1), List.of(), List.of(), List.of(events));
    }

    private static SceneOptions options() {
        return new SceneOptions(WIDTH, ABOVE, LIGHT, false, false, false);
    }

    private static Color at(BufferedImage image, double x, double y, double z) {
        Projection p = Projection.fit(world(), ABOVE, WIDTH, Projection.heightFor(world(), ABOVE, WIDTH),
                Double.NaN, Double.NaN);
        return new Color(image.getRGB((int) Math.round(p.px(x, y, z)), (int) Math.round(p.py(x, y, z))));
    }

    @Test
    void theSonarSwitchDrawsTheRaysOnTheFloor() {
        BufferedImage off = SolidRenderer.render(world(), snapshot(true), options(), null);
        BufferedImage on = SolidRenderer.render(world(), snapshot(true), options().withSensors(true, false), null);
        Color floor = Shading.shade(WorldRenderer.BACKGROUND, UP, LIGHT.towardsLight());

        // 300 mm past the robot's nose, along the ray: the floor without sonar, the robot's colour with it
        assertEquals(floor, at(off, 3500, 1500, 0));
        assertNotEquals(floor, at(on, 3500, 1500, 0), "a sonar ray on the floor");
        assertEquals(floor, at(on, 3500, 1300, 0), "beside the ray, the floor");
    }

    @Test
    void theLaserSwitchDrawsTheScanOnTheFloor() {
        BufferedImage off = SolidRenderer.render(world(), snapshot(true), options(), null);
        BufferedImage on = SolidRenderer.render(world(), snapshot(true), options().withSensors(false, true), null);

        // the hit of the middle beam: 150 mm (the laser's mount) + 600 mm ahead of the robot's centre
        assertNotEquals(at(off, 3750, 1500, 0), at(on, 3750, 1500, 0), "the laser's hit on the floor");
    }

    @Test
    void aRedBlockIsRedIn3D() {
        BufferedImage image = SolidRenderer.render(world(), null, options(), null);

        assertEquals(Shading.shade(Color.RED, UP, LIGHT.towardsLight()), at(image, 1250, 750, 500), "the block's roof");
    }

    @Test
    void aRobotGoneFromTheRunIsNoBlock() {
        BufferedImage connected = SolidRenderer.render(world(), snapshot(true), options(), null);
        BufferedImage gone = SolidRenderer.render(world(), snapshot(false,
                new Snapshot.Event("r1", "dropped", 7, "removed")), options(), null);
        Color floor = Shading.shade(WorldRenderer.BACKGROUND, UP, LIGHT.towardsLight());

        assertNotEquals(floor, at(connected, 2900, 1500, Projection.ROBOT_HEIGHT_MM), "a connected robot's roof");
        assertEquals(floor, at(gone, 2900, 1500, 0), "where a removed robot stopped, the floor shows");
    }

    @Test
    void theLegendIsDrawnUnderTheSceneAndSaysWhatThe3dViewShows() {
        SceneOptions shown = options().withSensors(true, true).withKey(true);
        BufferedImage image = SolidRenderer.render(world(), snapshot(true), shown, null);
        int scene = Projection.heightFor(world(), ABOVE, WIDTH);

        assertTrue(SolidRenderer.keyHeight(world(), shown) > 0);
        assertEquals(scene + SolidRenderer.keyHeight(world(), shown), image.getHeight());
        assertEquals(List.of("r1", "front (heading)", "grey: not connected yet",
                        "dashed grey: gone (left, dropped or removed)", "red edge: stalled", "sonar rays", "laser scan"),
                WorldRenderer.solidLegend(world(), shown.shown()));
        assertEquals(Color.WHITE, new Color(image.getRGB(WIDTH - 3, scene + 2)), "the key's paper");
        assertTrue(SolidRenderer.keyHeight(world(), options()) == 0, "no legend when the options show none");
        assertTrue(WorldRenderer.solidLegend(world(), new RenderOptions(WIDTH, false, false).withGrid(true))
                .stream().noneMatch(e -> e.startsWith("grid")), "the 3D view draws no grid");
    }
}
