package robosim.env.world.xml;

import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.Polygon;
import robosim.geometry.BodyShape;
import robosim.geometry.Pose2D;
import robosim.params.ParameterFileException;
import robosim.protocol.RobotKind;
import robosim.protocol.RobotParameters;
import robosim.params.RobotParametersReader;
import robosim.env.world.Bounds;
import robosim.env.world.Obstacle;
import robosim.env.world.RobotToPlace;
import robosim.params.RobotParameterFiles;
import robosim.env.world.RobotSpec;
import robosim.protocol.LogLimiter;
import robosim.protocol.RobotHello;

/**
 * Turns {@code <robot>} elements into {@link RobotSpec}s: reads each robot's parameter file
 * (relative to the world file, or a shipped one named as {@code p3dx}) and checks that its body,
 * as that file sizes it, starts inside the world and clear of the obstacles and of the robots placed before it.
 */
final class RobotPlacer {
    /** The robot types a world may name; {@code scout} is reserved for the Scout API. */
    static final List<String> TYPES = RobotKind.ids();

    private final Attributes attributes;
    private final Bounds bounds;
    private final List<Obstacle> obstacles;
    private final List<String> obstacleNames;
    /** Per obstacle its box, min x, min y, max x, max y: most obstacles are ruled out by it alone. */
    private final double[] boxes;
    private final List<Polygon> outlines = new ArrayList<>();
    private final GeometryFactory factory = new GeometryFactory();
    private final List<RobotSpec> placed = new ArrayList<>();
    private final Map<Path, RobotParameters> parameterCache = new HashMap<>();

    /**
     * @param obstacleNames how messages name each obstacle, in the order of {@code obstacles}
     */
    RobotPlacer(Attributes attributes, Bounds bounds, List<Obstacle> obstacles, List<String> obstacleNames) {
        this.attributes = attributes;
        this.bounds = bounds;
        this.obstacles = obstacles;
        this.obstacleNames = obstacleNames;
        // boxes rather than a GeometryClient: building its indexes for a map's 10^5 obstacles costs
        // more than checking a few robots against every box
        this.boxes = new double[4 * obstacles.size()];
        for (int i = 0; i < obstacles.size(); i++) {
            double[] xy = obstacles.get(i).xy();
            double minX = Double.POSITIVE_INFINITY;
            double minY = Double.POSITIVE_INFINITY;
            double maxX = Double.NEGATIVE_INFINITY;
            double maxY = Double.NEGATIVE_INFINITY;
            for (int k = 0; k < xy.length; k += 2) {
                minX = Math.min(minX, xy[k]);
                maxX = Math.max(maxX, xy[k]);
                minY = Math.min(minY, xy[k + 1]);
                maxY = Math.max(maxY, xy[k + 1]);
            }
            boxes[4 * i] = minX;
            boxes[4 * i + 1] = minY;
            boxes[4 * i + 2] = maxX;
            boxes[4 * i + 3] = maxY;
        }
    }

    /** @return the robot, checked and placed */
    RobotSpec place(RobotElement e) {
        String name = attributes.text(e, "name", e.name);
        checkName(e, name);
        String type = attributes.text(e, "type", e.type);
        double x = attributes.number(e, "x", e.x);
        double y = attributes.number(e, "y", e.y);
        double th = attributes.number(e, "th", e.th, 0);
        String params = attributes.text(e, "params", e.params);
        return place(e, name, type, x, y, th, params, parameterFile(e, name, params));
    }

    /**
     * The file a {@code params} attribute names: a path relative to the world file's directory, or,
     * when there is no such file, a shipped name such as {@code p3dx}.
     */
    private Path parameterFile(Element e, String name, String params) {
        Path relative = attributes.file().toAbsolutePath().getParent().resolve(params).normalize();
        if (Files.exists(relative)) {
            return relative;
        }
        Optional<Path> shipped = RobotParameterFiles.shipped(params);
        if (shipped.isPresent()) {
            return shipped.get().toAbsolutePath().normalize();
        }
        throw attributes.error(e, about(name, params) + " does not exist (looked for " + shown(relative, params)
                + ") and is no shipped name: params is a path relative to the world file's directory, or the name"
                + " of a file in " + RobotParameterFiles.shippedFolder().toAbsolutePath().normalize()
                + " (" + String.join(", ", RobotParameterFiles.shippedNames()) + ")");
    }

    /**
     * Places a robot asked for with {@code --robot}; its problems are reported with line 0, as the
     * option's, not the file's.
     *
     * @param robot   the option's robot
     * @param name    the robot's name
     * @param pose    where it starts
     * @return the robot, checked and placed
     */
    RobotSpec place(RobotToPlace robot, String name, Pose2D pose) {
        Element option = new RobotElement();
        Path file;
        try {
            file = RobotParameterFiles.resolve(robot.type()).toAbsolutePath().normalize();
        } catch (IllegalArgumentException ex) {
            throw attributes.error(option, "--robot " + robot + ": " + ex.getMessage());
        }
        String type = RobotKind.ofRobotClass(parameters(option, name, robot.type(), file).robotClass()).id();
        return place(option, name, type, pose.x(), pose.y(), Math.toDegrees(pose.th()), robot.type(), file);
    }

    private RobotSpec place(Element e, String name, String type, double x, double y, double th, String params,
                            Path file) {
        checkName(e, name);
        for (RobotSpec other : placed) {
            if (other.name().equals(name)) {
                throw attributes.error(e, "duplicate robot name '" + name + "': already used by the robot at line "
                        + other.line());
            }
        }
        if (!TYPES.contains(type)) {
            throw attributes.error(e, "robot '" + name + "' has unknown type " + Attributes.quote(type)
                    + "; known types: "
                    + String.join(", ", TYPES));
        }
        RobotSpec robot = new RobotSpec(name, type, x, y, th, file, parameters(e, name, params, file), e.line());
        check(robot, e);
        outlines.add(factory.createPolygon(robot.body().ringAt(robot.pose())));
        placed.add(robot);
        return robot;
    }

    /** @return how an error names a robot's parameter file: its {@code params} as an excerpt */
    private static String about(String name, String params) {
        return "robot '" + name + "': parameter file " + LogLimiter.excerpt(params);
    }

    /**
     * @return a path made of a {@code params} attribute as an error shows it: escaped, and for a
     *         {@code params} too long to quote whole, the world file's directory and its excerpt
     */
    private String shown(Path p, String params) {
        return LogLimiter.excerpt(params).equals(params) ? RobotHello.printable(p.toString(), 300)
                : RobotHello.printable(attributes.file().toAbsolutePath().getParent().toString(), 300) + "/"
                + LogLimiter.excerpt(params);
    }

    private void checkName(Element e, String name) {
        if (!RobotHello.validName(name)) {
            throw attributes.error(e, RobotHello.NAME_RULE + "; " + Attributes.quote(name) + " is not");
        }
    }

    private RobotParameters parameters(Element e, String name, String params, Path file) {
        RobotParameters known = parameterCache.get(file);
        if (known != null) {
            return known;
        }
        if (!Files.exists(file)) {
            throw attributes.error(e, about(name, params) + " does not exist (looked for "
                    + shown(file, params) + ")");
        }
        if (!Files.isRegularFile(file) || !Files.isReadable(file)) {
            throw attributes.error(e, about(name, params) + " cannot be read ("
                    + shown(file, params) + ")");
        }
        try {
            RobotParameters read = RobotParametersReader.read(file);
            String bad = read.violation();
            if (bad != null) {
                throw attributes.error(e, about(name, params) + " breaks a bound: " + bad);
            }
            parameterCache.put(file, read);
            return read;
        } catch (ParameterFileException ex) {
            throw attributes.error(e, "robot '" + name + "': broken parameter file: " + ex.getMessage());
        } catch (UncheckedIOException ex) {
            throw attributes.error(e, about(name, params) + " cannot be read ("
                    + LogLimiter.excerpt(ex.getCause().getMessage()) + ")");
        }
    }

    private void check(RobotSpec robot, Element e) {
        BodyShape body = robot.body();
        Pose2D pose = robot.pose();
        String where = "robot '" + robot.name() + "' at (" + Attributes.format(robot.x()) + ", "
                + Attributes.format(robot.y()) + ")";
        Coordinate[] ring = body.ringAt(pose);
        for (Coordinate c : ring) {
            if (!bounds.contains(c.x, c.y)) {
                throw attributes.error(e, where + " is outside the world " + bounds.describe()
                        + ": its body must lie inside it");
            }
        }
        // touching counts, as for the GeometryClient's overlaps: JTS's intersects
        Polygon outline = factory.createPolygon(ring);
        Envelope box = outline.getEnvelopeInternal();
        for (int i = 0; i < obstacles.size(); i++) {
            boolean near = boxes[4 * i] <= box.getMaxX() && boxes[4 * i + 2] >= box.getMinX()
                    && boxes[4 * i + 1] <= box.getMaxY() && boxes[4 * i + 3] >= box.getMinY();
            if (near && obstacles.get(i).polygon().intersects(outline)) {
                throw attributes.error(e, where + " overlaps " + obstacleNames.get(i));
            }
        }
        for (int i = 0; i < placed.size(); i++) {
            if (outlines.get(i).intersects(outline)) {
                throw attributes.error(e, where + " overlaps robot '" + placed.get(i).name() + "' at line "
                        + placed.get(i).line());
            }
        }
    }
}
