package robosim.viewer.draw;

import java.awt.Color;

/**
 * The colours robots are drawn in: one per robot, by its index in the world, so that a robot keeps
 * its colour from image to image and across the 2D, 3D and replay views.
 */
public final class RobotPalette {
    /** Fill for a robot whose program is not connected. */
    public static final Color DISCONNECTED = new Color(190, 190, 190);
    /** Outline for a robot that is stalled against something. */
    public static final Color STALLED = new Color(220, 0, 0);

    // Saturated, mutually distinct hues that are neither red (stall) nor grey (obstacle, offline).
    private static final Color[] COLOURS = {
        new Color(31, 119, 180), new Color(255, 127, 14), new Color(44, 160, 44),
        new Color(148, 103, 189), new Color(23, 190, 207), new Color(188, 189, 34),
        new Color(227, 119, 194), new Color(140, 86, 75),
    };

    private RobotPalette() {
    }

    /**
     * @param index the robot's index in the world, from 0; indexes past the palette wrap round
     * @return the robot's colour
     */
    public static Color colour(int index) {
        return COLOURS[Math.floorMod(index, COLOURS.length)];
    }

    /** @return how many distinct colours there are before they repeat */
    public static int size() {
        return COLOURS.length;
    }
}
