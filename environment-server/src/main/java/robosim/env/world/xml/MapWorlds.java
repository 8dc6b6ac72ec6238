package robosim.env.world.xml;

import java.nio.file.Path;
import java.util.AbstractList;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import robosim.comms.CommsSettings;
import robosim.env.world.Noise;
import robosim.env.world.Obstacle;
import robosim.env.world.RobotSpec;
import robosim.env.world.RobotToPlace;
import robosim.env.world.World;
import robosim.env.world.map.MapGeometry;
import robosim.geometry.Pose2D;
import robosim.map.MapFile;
import robosim.map.MapFileException;
import robosim.map.MapReader;

/**
 * Worlds made from ARIA maps: a {@code .map} file read as a world of its own, a {@code <map>}
 * element's file, and robots asked for with {@code --robot} placed at a world's homes.
 */
final class MapWorlds {
    /** The robot a map's world has when none is asked for. */
    static final RobotToPlace DEFAULT_ROBOT = new RobotToPlace("p3dx", null);
    /** How far each robot past the homes starts from the one before, along -y, mm (as MobileSim). */
    static final double ROBOT_SPACING = 1000;

    private MapWorlds() {
    }

    /** @return whether the file is read as a map rather than a world file: its name ends in {@code .map} */
    static boolean isMap(Path file) {
        Path name = file.getFileName();
        return name != null && name.toString().toLowerCase(Locale.ROOT).endsWith(".map");
    }

    /**
     * Reads a map as a world: its walls and points, its forbidden zones, and the robots to place
     * (one {@code p3dx} if none) at its homes.
     */
    static World read(Path file, List<RobotToPlace> toPlace) {
        MapGeometry map = geometry(file, file, 0);
        Attributes attributes = new Attributes(file);
        List<Obstacle> obstacles = map.obstacles();
        RobotPlacer placer = new RobotPlacer(attributes, map.bounds(), obstacles, names(obstacles));
        List<RobotSpec> robots = place(placer, toPlace.isEmpty() ? List.of(DEFAULT_ROBOT) : toPlace, map.homes());
        String name = file.getFileName().toString();
        name = name.substring(0, name.length() - ".map".length());
        return new World(name, file, map.bounds().width(), map.bounds().height(), WorldReader.DEFAULT_STEP_MS,
                obstacles, robots, List.of(), Noise.NONE, CommsSettings.DEFAULT, null, map.bounds().minX(),
                map.bounds().minY(), map.zones());
    }

    /**
     * Reads a map file, reporting its problems as the world file's.
     *
     * @param map    the map file
     * @param world  the file that names it (the map itself when read as a world)
     * @param line   the line of the {@code <map>} element, or 0
     */
    static MapGeometry geometry(Path map, Path world, int line) {
        try {
            MapFile read = MapReader.read(map);
            return MapGeometry.of(read);
        } catch (MapFileException e) {
            if (line == 0) {
                throw new WorldFileException(world, e.line(), e.rule(), e);
            }
            throw new WorldFileException(world, line, "map " + e.getMessage(), e);
        }
    }

    /**
     * Places the robots asked for: the first at the first home, each further one at the next home,
     * or, when the homes have run out, {@value #ROBOT_SPACING} mm along -y from the one before.
     */
    static List<RobotSpec> place(RobotPlacer placer, List<RobotToPlace> toPlace, List<Pose2D> homes) {
        List<String> names = RobotToPlace.names(toPlace);
        List<RobotSpec> robots = new ArrayList<>();
        Pose2D at = null;
        for (int i = 0; i < toPlace.size(); i++) {
            at = i < homes.size() ? homes.get(i) : new Pose2D(at.x(), at.y() - ROBOT_SPACING, at.th());
            robots.add(placer.place(toPlace.get(i), names.get(i), at));
        }
        return robots;
    }

    /** @return how messages name one of a map's obstacles */
    static String name(Obstacle obstacle) {
        return "the map's obstacle from line " + obstacle.line();
    }

    /** How messages name a map's obstacles, each made when asked: a map may have 10^5 of them. */
    private static List<String> names(List<Obstacle> obstacles) {
        return new AbstractList<>() {
            @Override
            public String get(int i) {
                return name(obstacles.get(i));
            }

            @Override
            public int size() {
                return obstacles.size();
            }
        };
    }
}
