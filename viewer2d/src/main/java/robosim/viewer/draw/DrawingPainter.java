package robosim.viewer.draw;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.util.function.Function;
import robosim.protocol.Colors;
import robosim.protocol.Figure;
import robosim.protocol.Snapshot;

/**
 * Draws the robots' drawings a snapshot carries (see {@link Drawings}): cells and polygons filled
 * translucent, lines and dots a little less so, each in the robot's colour unless the figure names
 * its own. Drawn over the floor and walls and under the robots, so a robot's known map and
 * claimed frontier show the division of work without hiding anything.
 */
final class DrawingPainter {
    /** Opacity of a filled figure, 0 to 255: the floor and walls show through. */
    static final int FILL_ALPHA = 90;
    /** Opacity of a line or a dot. */
    static final int LINE_ALPHA = 170;
    /** The diameter of a dot, px. */
    private static final double DOT_PX = 4;
    private static final BasicStroke LINE = new BasicStroke(2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND);

    private DrawingPainter() {
    }

    /**
     * @param g        where to draw
     * @param view     the world's transform
     * @param snapshot the drawings to draw, or null
     * @param colourOf each robot's colour, by name
     */
    static void draw(Graphics2D g, ViewTransform view, Snapshot snapshot, Function<String, Color> colourOf) {
        if (snapshot == null) {
            return;
        }
        g.setStroke(LINE);
        for (Snapshot.Drawing d : snapshot.drawings()) {
            Color robot = colourOf.apply(d.robot());
            for (Figure f : d.figures()) {
                Color c = f.color().isEmpty() ? robot : new Color(Colors.parse(f.color()));
                switch (f.kind()) {
                    case Figure.CELLS -> cells(g, view, f, translucent(c, FILL_ALPHA));
                    case Figure.POLYGON -> polygon(g, view, f, translucent(c, FILL_ALPHA));
                    case Figure.LINE -> line(g, view, f, translucent(c, LINE_ALPHA));
                    default -> dots(g, view, f, translucent(c, LINE_ALPHA));
                }
            }
        }
    }

    private static Color translucent(Color c, int alpha) {
        return new Color(c.getRed(), c.getGreen(), c.getBlue(), alpha);
    }

    /** One path of every cell, filled once, so that cells sharing an edge do not darken it. */
    private static void cells(Graphics2D g, ViewTransform view, Figure f, Color c) {
        Path2D.Double path = new Path2D.Double(Path2D.WIND_NON_ZERO);
        for (int i = 0; i + 3 < f.size(); i += 4) {
            double x0 = view.px(Math.min(f.at(i), f.at(i + 2)));
            double x1 = view.px(Math.max(f.at(i), f.at(i + 2)));
            double y0 = view.py(Math.max(f.at(i + 1), f.at(i + 3)));
            double y1 = view.py(Math.min(f.at(i + 1), f.at(i + 3)));
            path.append(new Rectangle2D.Double(x0, y0, x1 - x0, y1 - y0), false);
        }
        g.setColor(c);
        g.fill(path);
    }

    private static void polygon(Graphics2D g, ViewTransform view, Figure f, Color c) {
        g.setColor(c);
        g.fill(ClosedPath.of(f.size() / 2, i -> view.px(f.at(2 * i)), i -> view.py(f.at(2 * i + 1))));
    }

    private static void line(Graphics2D g, ViewTransform view, Figure f, Color c) {
        Path2D.Double path = new Path2D.Double();
        path.moveTo(view.px(f.at(0)), view.py(f.at(1)));
        for (int i = 2; i + 1 < f.size(); i += 2) {
            path.lineTo(view.px(f.at(i)), view.py(f.at(i + 1)));
        }
        g.setColor(c);
        g.draw(path);
    }

    private static void dots(Graphics2D g, ViewTransform view, Figure f, Color c) {
        g.setColor(c);
        for (int i = 0; i + 1 < f.size(); i += 2) {
            g.fill(new Ellipse2D.Double(view.px(f.at(i)) - DOT_PX / 2, view.py(f.at(i + 1)) - DOT_PX / 2, DOT_PX,
                    DOT_PX));
        }
    }
}
