package robosim.env.world;

import java.nio.file.Path;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import robosim.comms.CommsSettings;

/**
 * A world as read from a world file: its size, the length of one time step, the static
 * obstacles and the robots that must connect before the run starts. Coordinates are in mm, x to
 * the right and y up. The world covers x from {@code minX} to {@code minX + width} and y from
 * {@code minY} to {@code minY + height}: a world file's world starts at (0, 0); a map's world
 * keeps the map's own coordinates, which may be negative.
 *
 * @param name      the world's name, from the {@code name} attribute
 * @param source    the file it was read from
 * @param width     extent in x, mm, greater than 0
 * @param height    extent in y, mm, greater than 0
 * @param stepMs    simulated length of one time step, ms, from 1 to 10000
 * @param obstacles walls (as rectangles) and polygons, boundary walls first, then in file order
 * @param robots    the robots, in file order
 * @param heat      the heat sources, in file order
 * @param noise     the sensor and odometry noise of the world (none by default)
 * @param comms     how messages travel between robots at the start of a run
 *                  ({@link CommsSettings#DEFAULT} by default)
 * @param gold      the gold GoldFinder's robots look for (also one of the heat sources), or null
 * @param minX      the world's left edge, mm
 * @param minY      the world's bottom edge, mm
 * @param zones     the forbidden lines and areas of a map: kept for robot programs and viewers,
 *                  not solid
 * @param rules     who may join the run and when it ends ({@link RunRules#DEFAULT} by default)
 * @param objects   the movable objects (pucks) where they start, in file order
 * @param properties the world's {@code <property>} elements, name to value in file order: what robot
 *                  programs learn of the world in their welcome (none for an ARIA map)
 */
public record World(String name, Path source, double width, double height, int stepMs,
                    List<Obstacle> obstacles, List<RobotSpec> robots, List<HeatSource> heat, Noise noise,
                    CommsSettings comms, HeatSource gold, double minX, double minY, List<ForbiddenZone> zones,
                    RunRules rules, List<WorldObject> objects, Map<String, String> properties) {
    /** The widest and highest world a world file may describe, mm (100 km). */
    public static final double MAX_SIZE = 100_000_000;


    /**
     * The same world with only its first robots: a team smaller than the world has places for.
     *
     * @param count how many of the robots to keep, from 1 to the number there are
     * @return the world
     */
    public World withFirstRobots(int count) {
        if (count < 1 || count > robots.size()) {
            throw new IllegalArgumentException(count + " was supplied for the number of robots: world " + name
                    + " has places for 1 to " + robots.size());
        }
        return new World(name, source, width, height, stepMs, obstacles, robots.subList(0, count), heat, noise,
                comms, gold, minX, minY, zones, rules, objects, properties);
    }

    /**
     * The same world with other robots.
     *
     * @param others the robots, already placed and checked
     * @return the world
     */
    public World withRobots(List<RobotSpec> others) {
        return new World(name, source, width, height, stepMs, obstacles, others, heat, noise, comms, gold, minX, minY,
                zones, rules, objects, properties);
    }

    /**
     * The same world with other rules for joining and ending.
     *
     * @param other the rules
     * @return the world
     */
    public World withRules(RunRules other) {
        return new World(name, source, width, height, stepMs, obstacles, robots, heat, noise, comms, gold, minX, minY,
                zones, other, objects, properties);
    }

    /** @return the world's extent */
    public Bounds bounds() {
        return new Bounds(minX, minY, width, height);
    }

    /** Copies the lists and the properties, keeping their order, so the record stays immutable. */
    public World {
        properties = properties == null ? Map.of() : Collections.unmodifiableMap(new LinkedHashMap<>(properties));
        obstacles = List.copyOf(obstacles);
        robots = List.copyOf(robots);
        heat = List.copyOf(heat);
        zones = List.copyOf(zones);
        objects = objects == null ? List.of() : List.copyOf(objects);
        Objects.requireNonNull(comms, "comms");
        Objects.requireNonNull(rules, "rules");
    }

    /**
     * A world without properties.
     *
     * @param name      the world's name
     * @param source    the file it was read from
     * @param width     extent in x, mm
     * @param height    extent in y, mm
     * @param stepMs    step length, ms
     * @param obstacles walls and polygons
     * @param robots    the robots
     * @param heat      the heat sources
     * @param noise     the sensor and odometry noise
     * @param comms     how messages travel between robots
     * @param gold      the gold, or null
     * @param minX      the world's left edge, mm
     * @param minY      the world's bottom edge, mm
     * @param zones     the forbidden lines and areas of a map
     * @param rules     who may join the run and when it ends
     * @param objects   the movable objects
     */
    public World(String name, Path source, double width, double height, int stepMs,
                 List<Obstacle> obstacles, List<RobotSpec> robots, List<HeatSource> heat, Noise noise,
                 CommsSettings comms, HeatSource gold, double minX, double minY, List<ForbiddenZone> zones,
                 RunRules rules, List<WorldObject> objects) {
        this(name, source, width, height, stepMs, obstacles, robots, heat, noise, comms, gold, minX, minY, zones,
                rules, objects, Map.of());
    }

    /**
     * @param others the properties, name to value, already checked
     * @return the same world with those properties
     */
    public World withProperties(Map<String, String> others) {
        return new World(name, source, width, height, stepMs, obstacles, robots, heat, noise, comms, gold, minX, minY,
                zones, rules, objects, others);
    }

    /**
     * A world without movable objects.
     *
     * @param name      the world's name
     * @param source    the file it was read from
     * @param width     extent in x, mm
     * @param height    extent in y, mm
     * @param stepMs    step length, ms
     * @param obstacles walls and polygons
     * @param robots    the robots
     * @param heat      the heat sources
     * @param noise     the sensor and odometry noise
     * @param comms     how messages travel between robots
     * @param gold      the gold, or null
     * @param minX      the world's left edge, mm
     * @param minY      the world's bottom edge, mm
     * @param zones     the forbidden lines and areas of a map
     * @param rules     who may join the run and when it ends
     */
    public World(String name, Path source, double width, double height, int stepMs,
                 List<Obstacle> obstacles, List<RobotSpec> robots, List<HeatSource> heat, Noise noise,
                 CommsSettings comms, HeatSource gold, double minX, double minY, List<ForbiddenZone> zones,
                 RunRules rules) {
        this(name, source, width, height, stepMs, obstacles, robots, heat, noise, comms, gold, minX, minY, zones,
                rules, List.of());
    }

    /**
     * @param others the movable objects, already placed and checked
     * @return the same world with those objects
     */
    public World withObjects(List<WorldObject> others) {
        return new World(name, source, width, height, stepMs, obstacles, robots, heat, noise, comms, gold, minX, minY,
                zones, rules, others, properties);
    }

    /**
     * A world that ends as it always did and admits only the robots it names.
     *
     * @param name      the world's name
     * @param source    the file it was read from
     * @param width     extent in x, mm
     * @param height    extent in y, mm
     * @param stepMs    step length, ms
     * @param obstacles walls and polygons
     * @param robots    the robots
     * @param heat      the heat sources
     * @param noise     the sensor and odometry noise
     * @param comms     how messages travel between robots
     * @param gold      the gold, or null
     * @param minX      the world's left edge, mm
     * @param minY      the world's bottom edge, mm
     * @param zones     the forbidden lines and areas of a map
     */
    public World(String name, Path source, double width, double height, int stepMs,
                 List<Obstacle> obstacles, List<RobotSpec> robots, List<HeatSource> heat, Noise noise,
                 CommsSettings comms, HeatSource gold, double minX, double minY, List<ForbiddenZone> zones) {
        this(name, source, width, height, stepMs, obstacles, robots, heat, noise, comms, gold, minX, minY, zones,
                RunRules.DEFAULT);
    }

    /**
     * A world that starts at (0, 0) and has no forbidden zones, as a world file describes it.
     *
     * @param name      the world's name
     * @param source    the file it was read from
     * @param width     extent in x, mm
     * @param height    extent in y, mm
     * @param stepMs    step length, ms
     * @param obstacles walls and polygons
     * @param robots    the robots
     * @param heat      the heat sources
     * @param noise     the sensor and odometry noise
     * @param comms     how messages travel between robots
     * @param gold      the gold, or null
     */
    public World(String name, Path source, double width, double height, int stepMs,
                 List<Obstacle> obstacles, List<RobotSpec> robots, List<HeatSource> heat, Noise noise,
                 CommsSettings comms, HeatSource gold) {
        this(name, source, width, height, stepMs, obstacles, robots, heat, noise, comms, gold, 0, 0, List.of(),
                RunRules.DEFAULT);
    }

    /**
     * A world with the default communications settings.
     *
     * @param name      the world's name
     * @param source    the file it was read from
     * @param width     extent in x, mm
     * @param height    extent in y, mm
     * @param stepMs    step length, ms
     * @param obstacles walls and polygons
     * @param robots    the robots
     * @param heat      the heat sources
     * @param noise     the sensor and odometry noise
     */
    public World(String name, Path source, double width, double height, int stepMs,
                 List<Obstacle> obstacles, List<RobotSpec> robots, List<HeatSource> heat, Noise noise) {
        this(name, source, width, height, stepMs, obstacles, robots, heat, noise, CommsSettings.DEFAULT, null);
    }

    /**
     * A world without heat sources or noise, with the default communications settings.
     *
     * @param name      the world's name
     * @param source    the file it was read from
     * @param width     extent in x, mm
     * @param height    extent in y, mm
     * @param stepMs    step length, ms
     * @param obstacles walls and polygons
     * @param robots    the robots
     */
    public World(String name, Path source, double width, double height, int stepMs,
                 List<Obstacle> obstacles, List<RobotSpec> robots) {
        this(name, source, width, height, stepMs, obstacles, robots, List.of(), Noise.NONE);
    }
}
