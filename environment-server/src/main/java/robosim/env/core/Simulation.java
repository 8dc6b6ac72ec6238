package robosim.env.core;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.SplittableRandom;
import org.locationtech.jts.geom.Polygon;
import robosim.comms.CommsSettings;
import robosim.comms.Positions;
import robosim.env.world.HeatSource;
import robosim.env.world.Obstacle;
import robosim.env.world.RobotSpec;
import robosim.env.world.World;
import robosim.geometry.BodyShape;
import robosim.geometry.GeometryClient;
import robosim.geometry.Pose2D;
import robosim.protocol.Command;
import robosim.protocol.RobotState;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.RobotParameters;

/**
 * The simulation core: the world, its robots, and one {@link #step} at a time. No sockets,
 * threads, clocks or randomness; everything comes in as arguments, so a unit test can step it and
 * two runs with the same commands give the same trajectories.
 *
 * <p>Each step: every robot's commands are applied, then the robots move one after another in the
 * world file's order (each against the others' latest poses, so they can never overlap), then every
 * robot's sensors are read. Noise, when the world has any, comes from the seed alone.
 */
public final class Simulation {
    private final World world;
    private final long seed;
    private final List<Polygon> obstacles = new ArrayList<>();
    private GeometryClient geometry;
    private final Map<String, SimRobot> robots = new LinkedHashMap<>();
    private final MessageRouter messages;
    private final List<Snapshot.Said> said = new ArrayList<>();
    private Find find;
    private long step;

    /**
     * A simulation with seed 1.
     *
     * @param world the world, with its robots at their start poses
     */
    public Simulation(World world) {
        this(world, 1);
    }

    /**
     * @param world the world, with its robots at their start poses
     * @param seed  the seed of the run's noise: each robot draws from its own stream, split from it
     *              in the world file's order
     */
    public Simulation(World world, long seed) {
        this.world = world;
        this.seed = seed;
        for (Obstacle o : world.obstacles()) {
            obstacles.add(o.polygon());
        }
        rebuild(Map.of());
        // the messages' losses draw from a stream of their own, so they do not shift the robots' noise
        messages = new MessageRouter(robotNames(), world.comms(), new SplittableRandom(seed).nextLong() ^ 0x636f6d6d73L);
        readSensors();
    }

    /** Rebuilds the geometry with each robot's body from its (possibly replaced) parameters. */
    private void rebuild(Map<String, RobotParameters> replaced) {
        Map<String, SimRobot> old = new LinkedHashMap<>(robots);
        robots.clear();
        geometry = new GeometryClient(obstacles);
        SplittableRandom streams = new SplittableRandom(seed);
        for (RobotSpec spec : world.robots()) {
            SplittableRandom random = streams.split();
            SimRobot prev = old.get(spec.name());
            RobotParameters p = replaced.getOrDefault(spec.name(), prev != null ? prev.params : spec.parameters());
            BodyShape body = RobotSpec.bodyOf(p);
            int id = geometry.addBody(body, new Pose2D(spec.x(), spec.y(), Math.toRadians(spec.th())));
            SimRobot r = new SimRobot(spec.name(), spec.type(), p, body, id, spec.x(), spec.y(), spec.th(),
                    world.noise(), random);
            r.connected = prev != null && prev.connected;
            robots.put(spec.name(), r);
        }
    }

    /**
     * Gives a robot the parameters its program sent, before the first step: its body, limits and
     * sensor poses become the program's own.
     *
     * @param name   the robot
     * @param params its parameters
     * @throws IllegalStateException    if the run has started
     * @throws IllegalArgumentException if the robot is unknown or its new body would overlap
     *                                  something at its start pose
     */
    public void useParameters(String name, RobotParameters params) {
        if (step > 0) {
            throw new IllegalStateException("robot " + name + "'s parameters cannot change after step 0");
        }
        SimRobot r = robot(name);
        if (r.params.equals(params)) {
            return;
        }
        GeometryClient check = geometry;
        BodyShape body = RobotSpec.bodyOf(params);
        if (check.overlaps(body, r.pose(), r.bodyId)) {
            throw new IllegalArgumentException("robot " + name + " with its body of " + params.robotLength()
                    + " x " + params.robotWidth() + " mm overlaps something at its start pose");
        }
        rebuild(Map.of(name, params));
        readSensors();
    }

    /**
     * Advances the world one step.
     *
     * @param commands each robot's commands for this step, by name; robots absent keep their commands
     */
    public void step(Map<String, List<Command>> commands) {
        long current = step + 1;
        said.clear();
        for (SimRobot r : robots.values()) {
            List<Command> cs = commands.get(r.name);
            if (cs != null) {
                for (Command c : cs) {
                    apply(r, c, current);
                }
            }
        }
        double dt = world.stepMs() / 1000.0;
        for (SimRobot r : robots.values()) {
            r.move(geometry, dt);
        }
        step = current;
        readSensors();
        messages.deliver(step, positions(), connectedRobots());
    }

    /** Hands a command to what carries out its group, in the order the robot sent it. */
    private void apply(SimRobot r, Command c, long current) {
        if (c instanceof Command.Motion m) {
            r.drive(m);
        } else if (c instanceof Command.SensorSetting s) {
            r.sensors().configure(s);
        } else if (c instanceof Command.Messaging m) {
            messages.take(current, r.name, m);
        } else if (c instanceof Command.RunEvent e) {
            runEvent(r, e, current);
        } else {
            throw new IllegalStateException("no handler for the command group of " + c);
        }
    }

    private void runEvent(SimRobot r, Command.RunEvent e, long current) {
        if (e instanceof Command.Say say) {
            said.add(new Snapshot.Said(r.name, say.text()));
        } else if (e instanceof Command.ReportFound found) {
            reportFound(r, found.object(), current);
        } else {
            throw new IllegalStateException("no handler for the run event " + e);
        }
    }

    /** A robot's report of a find counts when its centre is this near the gold, mm. */
    public static final double GOLD_FOUND_DISTANCE = 1000;

    private void reportFound(SimRobot r, String object, long current) {
        HeatSource gold = world.gold();
        if (!"gold".equals(object) || gold == null) {
            messages.error(r.name, "robot " + r.name + " reported finding '" + object + "', but world "
                    + world.name() + " has no " + object);
            return;
        }
        double d = Math.hypot(r.x() - gold.x(), r.y() - gold.y());
        if (d > GOLD_FOUND_DISTANCE) {
            messages.error(r.name, "robot " + r.name + " reported the gold at step " + current + " but is "
                    + Math.round(d) + " mm from it; a find counts within " + Math.round(GOLD_FOUND_DISTANCE) + " mm");
        } else if (find == null) {
            find = new Find(r.name, current, d);
        }
    }

    /** @return the first confirmed find of the gold, or null */
    public Find find() {
        return find;
    }

    private Positions positions() {
        return new Positions() {
            @Override
            public double[] of(String robot) {
                SimRobot r = robot(robot);
                return new double[] {r.x(), r.y()};
            }

            @Override
            public boolean clear(String from, String to) {
                SimRobot a = robot(from);
                SimRobot b = robot(to);
                return geometry.lineOfSight(a.x(), a.y(), b.x(), b.y());
            }
        };
    }

    private Set<String> connectedRobots() {
        Set<String> c = new HashSet<>();
        for (SimRobot r : robots.values()) {
            if (r.connected) {
                c.add(r.name);
            }
        }
        return c;
    }

    /** @return how messages travel now */
    public CommsSettings commsSettings() {
        return messages.settings();
    }

    /**
     * Changes how messages travel, while the run goes on.
     *
     * @param settings the new settings
     */
    public void setCommsSettings(CommsSettings settings) {
        messages.setSettings(settings);
    }

    private void readSensors() {
        for (SimRobot r : robots.values()) {
            r.readSensors(geometry, world.heat());
        }
    }

    /**
     * Stops a robot whose program has left, so it stays where it is as an obstacle.
     *
     * @param name the robot
     */
    public void halt(String name) {
        robot(name).drive(new Command.Stop());
    }

    /** @return the number of steps taken */
    public long stepCount() {
        return step;
    }

    /** @return simulated time in ms */
    public long timeMs() {
        return step * world.stepMs();
    }

    /** @return the world simulated */
    public World world() {
        return world;
    }

    /** @return the robots' names, in the world file's order */
    public List<String> robotNames() {
        return Collections.unmodifiableList(new ArrayList<>(robots.keySet()));
    }

    /**
     * @param name a robot
     * @return what it knows of itself now
     */
    public RobotState state(String name) {
        return robot(name).state(step, timeMs(), messages.delivered(name), messages.errors(name));
    }

    /**
     * @param name a robot
     * @return its true pose, distance travelled and collisions
     */
    public RobotSummary summary(String name) {
        SimRobot r = robot(name);
        Odometry o = r.odometry();
        return new RobotSummary(r.name, r.x(), r.y(), r.th(), r.distance(), r.collisions(), r.stalled(),
                o.x(), o.y(), o.th());
    }

    /**
     * Marks a robot's program as connected or not, for viewers.
     *
     * @param name      the robot
     * @param connected whether its program is connected
     */
    public void setConnected(String name, boolean connected) {
        robot(name).connected = connected;
    }

    /** @return the moving parts of the world now, for viewers */
    public Snapshot snapshot() {
        List<Snapshot.RobotView> views = new ArrayList<>();
        for (SimRobot r : robots.values()) {
            Odometry o = r.odometry();
            views.add(new Snapshot.RobotView(r.name, r.x(), r.y(), r.th(), r.stalled(), r.connected,
                    r.sensors().sonar(), o.x(), o.y(), o.th(), r.sensors().laser(), r.sensors().laserIncrement(),
                    r.vel(), r.rotVel()));
        }
        return new Snapshot(step, timeMs(), views, messages.sentLastStep(), said);
    }

    /** @return the static world, for viewers */
    public WorldDescription description() {
        List<WorldDescription.Obstacle> obs = new ArrayList<>();
        for (Obstacle o : world.obstacles()) {
            obs.add(new WorldDescription.Obstacle(o.xy(), o.height()));
        }
        List<WorldDescription.RobotInfo> infos = new ArrayList<>();
        for (SimRobot r : robots.values()) {
            infos.add(new WorldDescription.RobotInfo(r.name, r.type, r.params));
        }
        List<WorldDescription.HeatSource> heat = new ArrayList<>();
        for (HeatSource h : world.heat()) {
            heat.add(new WorldDescription.HeatSource(h.x(), h.y(), h.intensity()));
        }
        return new WorldDescription(world.name(), world.width(), world.height(), world.stepMs(), obs, infos, heat);
    }

    /**
     * Whether a robot's body, where it stands, overlaps an obstacle or another robot.
     *
     * @param name the robot
     * @return true if it does
     */
    public boolean overlapsAnything(String name) {
        SimRobot r = robot(name);
        return geometry.overlaps(r.body, r.pose(), r.bodyId);
    }

    private SimRobot robot(String name) {
        SimRobot r = robots.get(name);
        if (r == null) {
            throw new IllegalArgumentException("no robot named '" + name + "' in world " + world.name());
        }
        return r;
    }
}
