package robosim.env.world.map;

import java.util.ArrayList;
import java.util.List;
import robosim.env.world.Bounds;
import robosim.env.world.ForbiddenZone;
import robosim.env.world.Obstacle;
import robosim.geometry.Pose2D;
import robosim.map.Cairn;
import robosim.map.Coordinates;
import robosim.map.MapFile;

/**
 * A map as the world sees it: its lines as thin walls, its points as small squares merged along
 * rows and columns, its forbidden lines and areas (not solid), the places robots start from, and
 * the rectangle it all lies in.
 *
 * @param obstacles the walls and point obstacles, lines first, in file order
 * @param zones     the forbidden lines and areas, in file order
 * @param homes     where robots start: the {@code RobotHome} cairns, else the {@code Dock} cairns,
 *                  else one place at the map's origin (or its centre when the origin lies outside
 *                  it); headings in radians
 * @param bounds    everything in the map, with {@value #MARGIN} mm to spare on each side
 */
public record MapGeometry(List<Obstacle> obstacles, List<ForbiddenZone> zones, List<Pose2D> homes, Bounds bounds) {
    /** The thickness of a map line as a wall, mm: ARIA's lines have none. */
    public static final double LINE_THICKNESS = 20;
    /** The side of a point's square when the map gives no {@code Resolution}, mm. */
    public static final double DEFAULT_RESOLUTION = 20;
    /** The largest side of a point's square, mm, whatever the map's resolution. */
    public static final double MAX_RESOLUTION = 1000;
    /** The height of the walls and points, mm, as a world file's default wall. */
    public static final double HEIGHT = 500;
    /** Room left around the map's contents, mm, so that a robot at its edge is inside the world. */
    public static final double MARGIN = 1000;

    /** Copies the lists so the record stays immutable. */
    public MapGeometry {
        obstacles = List.copyOf(obstacles);
        zones = List.copyOf(zones);
        homes = List.copyOf(homes);
    }

    /**
     * @param map what a map file holds
     * @return its geometry
     */
    public static MapGeometry of(MapFile map) {
        List<Obstacle> obstacles = new ArrayList<>();
        Extent extent = new Extent();
        Coordinates l = map.lineItems();
        for (int i = 0; i < l.count(); i++) {
            obstacles.add(wall(l.get(i, 0), l.get(i, 1), l.get(i, 2), l.get(i, 3), l.line(i)));
            extent.add(l.get(i, 0), l.get(i, 1));
            extent.add(l.get(i, 2), l.get(i, 3));
        }
        Coordinates p = map.pointItems();
        for (int i = 0; i < p.count(); i++) {
            extent.add(p.get(i, 0), p.get(i, 1));
        }
        double side = map.resolution() > 0 ? Math.min(map.resolution(), MAX_RESOLUTION) : DEFAULT_RESOLUTION;
        obstacles.addAll(new PointMerger(p, side, HEIGHT).merge());
        List<ForbiddenZone> zones = new ArrayList<>();
        List<Pose2D> robotHomes = new ArrayList<>();
        List<Pose2D> docks = new ArrayList<>();
        for (Cairn c : map.cairns()) {
            extent.add(c.x(), c.y());
            switch (c.type()) {
                case "ForbiddenLine" -> zones.add(new ForbiddenZone(false, c.fromTo(), c.label(), c.line()));
                case "ForbiddenArea" -> zones.add(new ForbiddenZone(true, corners(c), c.label(), c.line()));
                case "RobotHome" -> robotHomes.add(pose(c));
                case "Dock" -> docks.add(pose(c));
                default -> { } // goals and the like are for the robots' programs, not the world
            }
        }
        for (ForbiddenZone z : zones) {
            double[] xy = z.xy();
            for (int i = 0; i < xy.length; i += 2) {
                extent.add(xy[i], xy[i + 1]);
            }
        }
        Bounds bounds = extent.bounds();
        List<Pose2D> homes = !robotHomes.isEmpty() ? robotHomes : !docks.isEmpty() ? docks
                : List.of(bounds.contains(0, 0) ? new Pose2D(0, 0, 0)
                : new Pose2D(bounds.minX() + bounds.width() / 2, bounds.minY() + bounds.height() / 2, 0));
        return new MapGeometry(obstacles, zones, homes, bounds);
    }

    private static Pose2D pose(Cairn c) {
        return new Pose2D(c.x(), c.y(), Math.toRadians(c.th()));
    }

    /** An area's corners: its from and to points span a rectangle, turned by th about the origin (ARIA's rule). */
    private static double[] corners(Cairn c) {
        double[] ft = c.fromTo();
        double a = Math.toRadians(c.th());
        double sa = Math.sin(a);
        double ca = Math.cos(a);
        double[] local = {ft[0], ft[1], ft[2], ft[1], ft[2], ft[3], ft[0], ft[3]};
        double[] xy = new double[8];
        for (int i = 0; i < 8; i += 2) {
            xy[i] = local[i] * ca - local[i + 1] * sa;
            xy[i + 1] = local[i] * sa + local[i + 1] * ca;
        }
        return xy;
    }

    /** A line as a rectangle {@link #LINE_THICKNESS} wide, extended as much past each end; a dot as a square. */
    static Obstacle wall(double x1, double y1, double x2, double y2, int line) {
        double h = LINE_THICKNESS / 2;
        double len = Math.hypot(x2 - x1, y2 - y1);
        double ux = len == 0 ? 1 : (x2 - x1) / len;
        double uy = len == 0 ? 0 : (y2 - y1) / len;
        double ax = x1 - ux * h;
        double ay = y1 - uy * h;
        double bx = x2 + ux * h;
        double by = y2 + uy * h;
        double nx = -uy * h;
        double ny = ux * h;
        return new Obstacle(new double[] {ax - nx, ay - ny, bx - nx, by - ny, bx + nx, by + ny, ax + nx, ay + ny},
                HEIGHT, line);
    }

    /** The smallest rectangle holding what was added. */
    private static final class Extent {
        private double minX = Double.POSITIVE_INFINITY;
        private double minY = Double.POSITIVE_INFINITY;
        private double maxX = Double.NEGATIVE_INFINITY;
        private double maxY = Double.NEGATIVE_INFINITY;

        void add(double x, double y) {
            minX = Math.min(minX, x);
            minY = Math.min(minY, y);
            maxX = Math.max(maxX, x);
            maxY = Math.max(maxY, y);
        }

        Bounds bounds() {
            if (minX > maxX) {
                add(0, 0);
            }
            double x0 = Math.floor(minX - MARGIN);
            double y0 = Math.floor(minY - MARGIN);
            return new Bounds(x0, y0, Math.ceil(maxX + MARGIN) - x0, Math.ceil(maxY + MARGIN) - y0);
        }
    }
}
