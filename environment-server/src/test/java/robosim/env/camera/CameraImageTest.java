package robosim.env.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.ColorBlob;

/** The image a camera at the origin, 300 mm up, facing +x with a 45° field of view, renders. */
class CameraImageTest {
    private static final double FOV = Math.toRadians(45);
    private static final int RED = 0xff0000;

    private static ColoredShape box(double x0, double x1, double halfWidth, double height, int rgb) {
        return new ColoredShape(new double[] {x0, -halfWidth, x1, -halfWidth, x1, halfWidth, x0, halfWidth},
                height, rgb, -1);
    }

    private static List<ColorBlob> red(List<ColoredShape> shapes, double tilt) {
        int[] image = CameraImage.render(0, 0, 300, 0, tilt, FOV, shapes, -1);
        int[] channels = new int[32];
        java.util.Arrays.fill(channels, ColoredShape.NO_COLOR);
        channels[0] = RED;
        return BlobFinder.find(image, channels);
    }

    @Test
    void aTallRedWallShowsAboveALowerGreyBoxBeforeIt() {
        ColoredShape wall = box(3000, 3100, 2000, 2000, RED);
        ColoredShape low = box(1000, 1200, 3000, 250, ColoredShape.NO_COLOR);
        List<ColorBlob> alone = red(List.of(wall), 0);
        List<ColorBlob> behind = red(List.of(low, wall), 0);
        assertEquals(1, behind.size());
        assertTrue(behind.get(0).bottom() < alone.get(0).bottom(), "the box hides the wall's foot: " + behind);
        assertEquals(alone.get(0).top(), behind.get(0).top(), "but not its top");
        // the box's top, 50 mm below the lens at 1000 mm, is 0.05 below the axis, where the image's
        // half-height is tan(22.5°)·3/4 over 60 rows: the box fills the rows whose centres lie below it,
        // and the wall shows down to the row above those
        double boxTop = 60 + 0.05 / (Math.tan(FOV / 2) * 0.75) * 60;
        assertEquals(Math.ceil(boxTop - 0.5) - 1, behind.get(0).bottom());
    }

    @Test
    void tiltingDownMovesTheBlobUpTheImage() {
        ColoredShape box = box(2000, 2300, 200, 500, RED);
        ColorBlob level = red(List.of(box), 0).get(0);
        ColorBlob down = red(List.of(box), Math.toRadians(-10)).get(0);
        assertTrue(down.ycg() < level.ycg(), level + " then " + down);
        assertEquals(level.xcg(), down.xcg());
    }

    @Test
    void aShapeBehindTheCameraIsNotSeen() {
        assertEquals(List.of(), red(List.of(box(-2300, -2000, 200, 500, RED)), 0));
    }

    @Test
    void theCameraDoesNotSeeItsOwnBody() {
        ColoredShape own = new ColoredShape(new double[] {-200, -200, 200, -200, 200, 200, -200, 200}, 1000, RED, 7);
        int[] channels = new int[32];
        java.util.Arrays.fill(channels, ColoredShape.NO_COLOR);
        channels[0] = RED;
        assertEquals(List.of(), BlobFinder.find(CameraImage.render(0, 0, 300, 0, 0, FOV, List.of(own), 7), channels));
        assertEquals(1, BlobFinder.find(CameraImage.render(0, 0, 300, 0, 0, FOV, List.of(own), -1), channels).size(),
                "another robot's camera inside it would");
    }
}
