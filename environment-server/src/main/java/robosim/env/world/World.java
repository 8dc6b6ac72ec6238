package robosim.env.world;

import java.nio.file.Path;
import java.util.List;

/**
 * A world as read from a world file: its size, the length of one time step, the static
 * obstacles and the robots that must connect before the run starts. Coordinates are in mm with
 * the origin at the lower left corner of the world, x to the right and y up.
 *
 * @param name      the world's name, from the {@code name} attribute
 * @param source    the file it was read from
 * @param width     extent in x, mm, greater than 0
 * @param height    extent in y, mm, greater than 0
 * @param stepMs    simulated length of one time step, ms, from 1 to 10000
 * @param obstacles walls (as rectangles) and polygons, boundary walls first, then in file order
 * @param robots    the robots, in file order
 */
public record World(String name, Path source, double width, double height, int stepMs,
                    List<Obstacle> obstacles, List<RobotSpec> robots) {

    /** Copies the lists so the record stays immutable. */
    public World {
        obstacles = List.copyOf(obstacles);
        robots = List.copyOf(robots);
    }
}
