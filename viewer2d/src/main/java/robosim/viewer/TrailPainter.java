package robosim.viewer;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Path2D;
import java.util.function.Function;

/** Draws each robot's path as a thin line in its own colour; the {@link WorldRenderer}'s helper. */
final class TrailPainter {
    /** Opacity of a trail, 0 to 255: clear, yet lighter than the robot itself. */
    static final int ALPHA = 150;

    void draw(Graphics2D g, ViewTransform view, Trails trails, Function<String, Color> colourOf) {
        g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        for (String robot : trails.robots()) {
            double[] xy = trails.points(robot);
            if (xy.length < 4) {
                continue;
            }
            Path2D.Double path = new Path2D.Double();
            path.moveTo(view.px(xy[0]), view.py(xy[1]));
            for (int i = 2; i + 1 < xy.length; i += 2) {
                path.lineTo(view.px(xy[i]), view.py(xy[i + 1]));
            }
            Color c = colourOf.apply(robot);
            g.setColor(new Color(c.getRed(), c.getGreen(), c.getBlue(), ALPHA));
            g.draw(path);
        }
    }
}
