package robosim.env.world.xml;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import robosim.comms.CommsSettings;
import robosim.env.world.Bounds;
import robosim.env.world.RobotToPlace;
import robosim.env.world.World;
import robosim.env.world.map.MapGeometry;
import robosim.geometry.Pose2D;
import robosim.env.world.Obstacle;
import robosim.env.world.HeatSource;
import robosim.env.world.Noise;
import robosim.env.world.RobotSpec;
import robosim.env.world.WorldObject;

/**
 * Reads a world file (see {@code docs/WORLD-FORMAT.md}) into a {@link World}, checking every
 * rule of the format. The first broken rule stops reading with a {@link WorldFileException} that
 * names the file, the line of the offending element and the rule.
 */
public final class WorldReader {
    /** Step length of a world without a {@code stepMs} attribute, ms. */
    public static final int DEFAULT_STEP_MS = 100;

    private WorldReader() {
    }

    /**
     * Reads and checks a world file, and the robot parameter files it names. A file whose name
     * ends in {@code .map} is read as an ARIA map, with one {@code p3dx} robot at its first home.
     *
     * @param file the world file
     * @return the world
     * @throws WorldFileException if the file cannot be read or breaks a rule of the format
     */
    public static World read(Path file) {
        return read(file, List.of());
    }

    /**
     * Reads and checks a world file, or an ARIA map ({@code .map}), adding the robots asked for
     * with {@code --robot} after the world's own, at its homes: the map's {@code RobotHome} cairns
     * (else {@code Dock} cairns, else its origin), or for a world without a map its centre. The
     * first goes to the first home, each further one to the next, or when they run out 1 m along
     * -y from the one before.
     *
     * @param file     the world or map file
     * @param toPlace  robots to add; for a map, none means one {@code p3dx}
     * @return the world
     * @throws WorldFileException if a file cannot be read or breaks a rule of the format, or a
     *                            requested robot cannot be placed (the message then names it)
     */
    public static World read(Path file, List<RobotToPlace> toPlace) {
        if (MapWorlds.isMap(file)) {
            return MapWorlds.read(file, toPlace);
        }
        WorldElement root = ElementReader.read(file);
        Attributes attributes = new Attributes(file);
        String name = attributes.name(root, "name", root.name);
        MapElement mapElement = mapElement(attributes, root);
        MapGeometry map = mapElement == null ? null : MapWorlds.geometry(
                file.toAbsolutePath().getParent().resolve(attributes.text(mapElement, "file", mapElement.file)),
                file, mapElement.line());
        Bounds bounds;
        if (map != null && root.width == null && root.height == null) {
            bounds = map.bounds();
        } else {
            bounds = new Bounds(0, 0,
                    attributes.atMost(root, "width", attributes.positive(root, "width", root.width), World.MAX_SIZE),
                    attributes.atMost(root, "height", attributes.positive(root, "height", root.height),
                            World.MAX_SIZE));
        }
        double width = bounds.width();
        double height = bounds.height();
        int stepMs = attributes.wholeNumber(root, "stepMs", root.stepMs, DEFAULT_STEP_MS, 1, 10_000);
        boolean boundary = attributes.bool(root, "boundary", root.boundary, false);

        List<Obstacle> obstacles = new ArrayList<>();
        List<String> obstacleNames = new ArrayList<>();
        if (boundary) {
            for (Obstacle wall : ObstacleFactory.boundary(width, height, root.line())) {
                obstacles.add(ObstacleFactory.moved(wall, bounds.minX(), bounds.minY()));
                obstacleNames.add("a boundary wall");
            }
        }
        ObstacleFactory shapes = new ObstacleFactory(attributes);
        NoiseElement noiseElement = null;
        CommsElement commsElement = null;
        for (Element child : root.children) {
            if (child instanceof WallElement wall) {
                obstacles.add(shapes.wall(wall));
                obstacleNames.add("the wall at line " + wall.line());
            } else if (child instanceof PolygonElement polygon) {
                obstacles.add(shapes.polygon(polygon));
                obstacleNames.add("the polygon at line " + polygon.line());
            } else if (child instanceof MapElement) {
                for (Obstacle o : map.obstacles()) {
                    obstacles.add(o);
                    obstacleNames.add(MapWorlds.name(o));
                }
            } else if (child instanceof NoiseElement noise) {
                if (noiseElement != null) {
                    throw attributes.error(noise, "a world has at most one <noise>; the first is at line "
                            + noiseElement.line());
                }
                noiseElement = noise;
            } else if (child instanceof CommsElement comms) {
                if (commsElement != null) {
                    throw attributes.error(comms, "a world has at most one <comms>; the first is at line "
                            + commsElement.line());
                }
                commsElement = comms;
            }
        }
        Noise noise = noiseElement == null ? Noise.NONE : noise(attributes, noiseElement);
        CommsSettings comms = commsElement == null ? CommsSettings.DEFAULT : comms(attributes, commsElement);
        // Robots and heat sources are checked against every obstacle, those listed after them too.
        RobotPlacer placer = new RobotPlacer(attributes, bounds, obstacles, obstacleNames);
        HeatPlacer heatPlacer = new HeatPlacer(attributes, bounds, obstacles, obstacleNames);
        List<RobotSpec> robots = new ArrayList<>();
        List<HeatSource> heat = new ArrayList<>();
        HeatSource gold = null;
        int goldLine = 0;
        for (Element child : root.children) {
            if (child instanceof RobotElement robot) {
                robots.add(placer.place(robot));
            } else if (child instanceof GoldElement g) {
                if (gold != null) {
                    throw attributes.error(g, "a world has at most one <gold>; the first is at line " + goldLine);
                }
                gold = heatPlacer.place(g);
                goldLine = g.line();
                heat.add(gold);
            } else if (child instanceof HeatElement source) {
                heat.add(heatPlacer.place(source));
            }
        }
        List<Pose2D> homes = map != null ? map.homes()
                : List.of(new Pose2D(bounds.minX() + width / 2, bounds.minY() + height / 2, 0));
        robots.addAll(MapWorlds.place(placer, toPlace, homes));
        ObjectPlacer objectPlacer = new ObjectPlacer(attributes, bounds, obstacles, obstacleNames, robots);
        List<WorldObject> objects = new ArrayList<>();
        for (Element child : root.children) {
            if (child instanceof ObjectElement object) {
                objects.add(objectPlacer.place(object));
            }
        }
        return new World(name, file, width, height, stepMs, obstacles, robots, heat, noise, comms, gold, bounds.minX(),
                bounds.minY(), map == null ? List.of() : map.zones(), RunRulesReader.read(attributes, root, bounds, gold),
                objects, PropertiesReader.read(attributes, root));
    }

    /** @return the world's {@code <map>}, or null; a world has at most one */
    private static MapElement mapElement(Attributes attributes, WorldElement root) {
        MapElement found = null;
        for (Element child : root.children) {
            if (child instanceof MapElement m) {
                if (found != null) {
                    throw attributes.error(m, "a world has at most one <map>; the first is at line " + found.line());
                }
                found = m;
            }
        }
        return found;
    }

    private static Noise noise(Attributes attributes, NoiseElement e) {
        return new Noise(attributes.nonNegative(e, "sonar", e.sonar, 0),
                attributes.nonNegative(e, "laser", e.laser, 0),
                attributes.nonNegative(e, "odometry", e.odometry, 0));
    }

    private static CommsSettings comms(Attributes attributes, CommsElement e) {
        CommsSettings d = CommsSettings.DEFAULT;
        return new CommsSettings(attributes.nonNegative(e, "range", e.range, d.maxRange()),
                attributes.bool(e, "wallsBlock", e.wallsBlock, d.wallsBlock()),
                attributes.wholeNumber(e, "latency", e.latency, d.latencySteps(), 1),
                attributes.between(e, "loss", e.loss, d.lossProbability(), 0, 1),
                attributes.wholeNumber(e, "maxBytes", e.maxBytes, d.maxMessageBytes(), 1));
    }
}
