package robosim.protocol;

import java.util.List;

/**
 * The static world, sent once to every viewer that attaches.
 *
 * @param name      the world's name
 * @param width     world width in mm (x from 0)
 * @param height    world height in mm (y from 0)
 * @param stepMs    step length in simulated ms
 * @param obstacles walls and obstacles as polygons
 * @param robots    the robots of the world and their bodies
 * @param heat      the heat sources
 */
public record WorldDescription(String name, double width, double height, int stepMs,
                               List<Obstacle> obstacles, List<RobotInfo> robots, List<HeatSource> heat)
        implements Message {
    /** Copies the lists so the record stays immutable. */
    public WorldDescription {
        obstacles = List.copyOf(obstacles);
        robots = List.copyOf(robots);
        heat = List.copyOf(heat);
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
     * A heat source.
     *
     * @param x         mm
     * @param y         mm
     * @param intensity its intensity at 1 m
     */
    public record HeatSource(double x, double y, double intensity) { }

    /**
     * A wall or obstacle.
     *
     * @param xy     the outer ring as x0, y0, x1, y1, ... (not closed)
     * @param height height in mm, for 3D views
     */
    public record Obstacle(double[] xy, double height) { }

    /**
     * A robot as the viewer draws it.
     *
     * @param name       the robot's name
     * @param robotType  its type
     * @param parameters its body and sensor poses
     */
    public record RobotInfo(String name, String robotType, RobotParameters parameters) { }
}
