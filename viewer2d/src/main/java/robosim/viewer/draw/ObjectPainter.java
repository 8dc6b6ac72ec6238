package robosim.viewer.draw;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Ellipse2D;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;

/**
 * Draws the world's movable objects (pucks) where the snapshot puts them, or where they start when
 * there is no snapshot (or it is from a recording made before worlds had objects): a disc in the
 * object's colour with a dark rim; one held off the floor by a gripper gets a second, white rim.
 */
final class ObjectPainter {
    /** The stroke of a lifted object's rim. */
    private static final BasicStroke RIM_STROKE = new BasicStroke(1f);
    /** An object's colour when its world file names none, or names one not listed here. */
    static final Color DEFAULT = new Color(230, 120, 20);
    /** The smallest disc drawn, px across, so that a puck stays visible in a large world. */
    static final double MIN_DIAMETER = 4;
    private static final Color RIM = new Color(40, 40, 40);
    private static final Map<String, Color> NAMES = Map.ofEntries(
            Map.entry("red", new Color(210, 40, 40)), Map.entry("green", new Color(40, 160, 60)),
            Map.entry("blue", new Color(40, 80, 210)), Map.entry("yellow", new Color(230, 200, 30)),
            Map.entry("orange", DEFAULT), Map.entry("black", new Color(20, 20, 20)),
            Map.entry("white", new Color(250, 250, 250)), Map.entry("purple", new Color(130, 50, 170)),
            Map.entry("cyan", new Color(30, 190, 200)), Map.entry("magenta", new Color(200, 40, 160)),
            Map.entry("grey", Color.GRAY), Map.entry("gray", Color.GRAY));

    private ObjectPainter() {
    }

    /**
     * @param g        where to draw
     * @param view     the world's transform
     * @param world    the objects and their colours
     * @param snapshot where they are now, or null
     */
    static void draw(Graphics2D g, ViewTransform view, WorldDescription world, Snapshot snapshot) {
        List<WorldDescription.WorldObject> objects = world.objects();
        List<Snapshot.ObjectView> now = snapshot == null ? List.of() : snapshot.objects();
        for (int i = 0; i < objects.size(); i++) {
            WorldDescription.WorldObject o = objects.get(i);
            boolean known = i < now.size();
            double x = known ? now.get(i).x() : o.x();
            double y = known ? now.get(i).y() : o.y();
            double d = Math.max(MIN_DIAMETER, 2 * o.radius() * view.scale());
            Ellipse2D disc = new Ellipse2D.Double(view.px(x) - d / 2, view.py(y) - d / 2, d, d);
            g.setColor(colour(o.color()));
            g.fill(disc);
            g.setColor(RIM);
            g.setStroke(RIM_STROKE);
            g.draw(disc);
            if (known && now.get(i).lifted()) {
                g.setColor(Color.WHITE);
                g.draw(new Ellipse2D.Double(view.px(x) - d / 2 + 2, view.py(y) - d / 2 + 2, d - 4, d - 4));
            }
        }
    }

    /** @return the colour a world file names: a name listed above or {@code #rrggbb}; else {@link #DEFAULT} */
    static Color colour(String name) {
        if (name == null) {
            return DEFAULT;
        }
        if (name.startsWith("#") && name.length() == 7) {
            try {
                return new Color(Integer.parseInt(name.substring(1), 16));
            } catch (NumberFormatException e) {
                return DEFAULT;
            }
        }
        return NAMES.getOrDefault(name.toLowerCase(Locale.ROOT), DEFAULT);
    }
}
