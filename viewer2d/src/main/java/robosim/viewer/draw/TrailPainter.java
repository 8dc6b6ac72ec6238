package robosim.viewer.draw;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Path2D;
import java.util.function.Function;

/**
 * Draws each robot's path as a thin line in its own colour, each piece apart (no line across a
 * jump), in any view: the caller says where a
 * point of the ground lands on the screen.
 */
public final class TrailPainter {
    /** Opacity of a trail, 0 to 255: clear, yet lighter than the robot itself. */
    static final int ALPHA = 150;

    /** Where a point of the ground (mm) lands on the screen. */
    @FunctionalInterface
    public interface ToScreen {
        /**
         * @param x   mm
         * @param y   mm
         * @param out receives the screen x and y
         */
        void map(double x, double y, double[] out);
    }

    private TrailPainter() {
    }

    /**
     * @param g        where to draw
     * @param trails   the paths
     * @param colourOf each robot's colour, by name
     * @param toScreen the view's projection of the ground
     */
    public static void draw(Graphics2D g, Trails trails, Function<String, Color> colourOf, ToScreen toScreen) {
        g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        double[] screen = new double[2];
        trails.forEach((robot, xy, from, to) -> {
            if (to - from < 2) {
                return;
            }
            Path2D.Double path = new Path2D.Double();
            toScreen.map(xy[2 * from], xy[2 * from + 1], screen);
            path.moveTo(screen[0], screen[1]);
            for (int i = from + 1; i < to; i++) {
                toScreen.map(xy[2 * i], xy[2 * i + 1], screen);
                path.lineTo(screen[0], screen[1]);
            }
            Color c = colourOf.apply(robot);
            g.setColor(new Color(c.getRed(), c.getGreen(), c.getBlue(), ALPHA));
            g.draw(path);
        });
    }
}
