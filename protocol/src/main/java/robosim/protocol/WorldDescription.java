package robosim.protocol;

import java.util.List;
import robosim.protocol.params.RobotParameters;

/**
 * The static world, sent once to every viewer that attaches.
 *
 * @param name      the world's name
 * @param width     world width in mm (x from 0)
 * @param height    world height in mm (y from 0)
 * @param stepMs    step length in simulated ms
 * @param obstacles walls and obstacles as polygons
 * @param robots    the robots of the world and their bodies
 */
public record WorldDescription(String name, double width, double height, int stepMs,
                               List<Obstacle> obstacles, List<RobotInfo> robots) implements Message {
    /** Copies the lists so the record stays immutable. */
    public WorldDescription {
        obstacles = List.copyOf(obstacles);
        robots = List.copyOf(robots);
    }

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
