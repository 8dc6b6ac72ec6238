package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.annotation.JsonSetter;
import com.fasterxml.jackson.annotation.Nulls;
import java.util.List;

/**
 * The static world, sent once to every viewer that attaches.
 *
 * @param name      the world's name
 * @param width     world width in mm (x from minX)
 * @param height    world height in mm (y from minY)
 * @param stepMs    step length in simulated ms
 * @param obstacles walls and obstacles as polygons
 * @param robots    the robots of the world and their bodies
 * @param heat      the heat sources
 * @param minX      the world's left edge, mm: 0 for a world file, a map's own for a map
 * @param minY      the world's bottom edge, mm
 * @param zones     a map's forbidden lines and areas, which are not solid
 * @param objects   the world's movable objects (pucks) where they start, in the world file's order;
 *                  where they are later comes in each {@link Snapshot}
 *
 * <p>A description without {@code minX}, {@code minY} or {@code zones}, as recordings made before
 * maps hold them, reads as a world from (0, 0) without zones.
 */
public record WorldDescription(String name, double width, double height, int stepMs,
                               List<Obstacle> obstacles, List<RobotInfo> robots, List<HeatSource> heat,
                               @JsonSetter(nulls = Nulls.AS_EMPTY) double minX,
                               @JsonSetter(nulls = Nulls.AS_EMPTY) double minY, List<Zone> zones,
                               @JsonInclude(JsonInclude.Include.NON_EMPTY) List<WorldObject> objects)
        implements Message {
    /** Copies the lists so the record stays immutable; an absent list of zones reads as none. */
    public WorldDescription {
        obstacles = List.copyOf(obstacles);
        robots = List.copyOf(robots);
        heat = List.copyOf(heat);
        zones = zones == null ? List.of() : List.copyOf(zones);
        objects = objects == null ? List.of() : List.copyOf(objects);
    }

    /**
     * A world from (0, 0) without forbidden zones.
     *
     * @param name      the world's name
     * @param width     mm
     * @param height    mm
     * @param stepMs    step length, ms
     * @param obstacles walls and obstacles
     * @param robots    robots
     * @param heat      the heat sources
     */
    public WorldDescription(String name, double width, double height, int stepMs,
                            List<Obstacle> obstacles, List<RobotInfo> robots, List<HeatSource> heat) {
        this(name, width, height, stepMs, obstacles, robots, heat, 0, 0, List.of());
    }

    /**
     * A world without heat sources.
     *
     * @param name      the world's name
     * @param width     mm
     * @param height    mm
     * @param stepMs    step length, ms
     * @param obstacles walls and obstacles
     * @param robots    robots
     */
    public WorldDescription(String name, double width, double height, int stepMs,
                            List<Obstacle> obstacles, List<RobotInfo> robots) {
        this(name, width, height, stepMs, obstacles, robots, List.of());
    }

    /**
     * A forbidden line or area of a map: drawn, never solid.
     *
     * @param area  whether it is an area (four corners) rather than a line (two ends)
     * @param xy    the points x0, y0, x1, y1, ...
     * @param label its label, possibly empty
     */
    public record Zone(boolean area, double[] xy, String label) { }

    /**
     * A heat source.
     *
     * @param x         mm
     * @param y         mm
     * @param intensity its intensity at 1 m
     * @param gold      whether it is the world's gold (GoldFinder's target, which glows), not a plain
     *                  {@code <heat>}; absent (read as false) in recordings made before it was sent
     */
    public record HeatSource(double x, double y, double intensity,
                             @JsonInclude(JsonInclude.Include.NON_DEFAULT)
                             @JsonSetter(nulls = Nulls.AS_EMPTY) boolean gold) {
        /**
         * A plain heat source, not the gold.
         *
         * @param x         mm
         * @param y         mm
         * @param intensity its intensity at 1 m
         */
        public HeatSource(double x, double y, double intensity) {
            this(x, y, intensity, false);
        }
    }

    /**
     * A wall or obstacle.
     *
     * @param xy     the outer ring as x0, y0, x1, y1, ... (not closed)
     * @param height height in mm, for 3D views
     * @param color  its colour as the world file names it (a name or {@code #rrggbb}, see
     *               {@link Colors}), or null for none; absent in recordings made before it was sent
     */
    public record Obstacle(double[] xy, double height,
                           @JsonInclude(JsonInclude.Include.NON_NULL) String color) {
        /**
         * An obstacle without a colour of its own.
         *
         * @param xy     the outer ring as x0, y0, x1, y1, ... (not closed)
         * @param height height in mm
         */
        public Obstacle(double[] xy, double height) {
            this(xy, height, null);
        }
    }

    /**
     * A robot as the viewer draws it.
     *
     * @param name       the robot's name
     * @param robotType  its type
     * @param parameters its body and sensor poses
     */
    public record RobotInfo(String name, String robotType, RobotParameters parameters) { }

    /**
     * A description without world objects.
     *
     * @param name      the world's name
     * @param width     mm
     * @param height    mm
     * @param stepMs    step length, ms
     * @param obstacles walls and obstacles
     * @param robots    robots
     * @param heat      the heat sources
     * @param minX      the world's left edge, mm
     * @param minY      the world's bottom edge, mm
     * @param zones     a map's forbidden lines and areas
     */
    public WorldDescription(String name, double width, double height, int stepMs, List<Obstacle> obstacles,
                            List<RobotInfo> robots, List<HeatSource> heat, double minX, double minY, List<Zone> zones) {
        this(name, width, height, stepMs, obstacles, robots, heat, minX, minY, zones, List.of());
    }

    /**
     * @param others the world's movable objects where they start
     * @return this description with those objects
     */
    public WorldDescription withObjects(List<WorldObject> others) {
        return new WorldDescription(name, width, height, stepMs, obstacles, robots, heat, minX, minY, zones, others);
    }

    /**
     * A movable object of the world, as its {@code <object>} element gives it.
     *
     * @param type   its type, {@code puck}
     * @param x      where it starts, mm
     * @param y      where it starts, mm
     * @param radius mm
     * @param color  its colour as the world file names it (for cameras and viewers), or null
     */
    public record WorldObject(String type, double x, double y, double radius,
                              @JsonInclude(JsonInclude.Include.NON_NULL) String color) { }
}
