package robosim.env.core;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.function.Supplier;
import java.util.random.RandomGenerator;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Polygon;
import robosim.comms.CommsSettings;
import robosim.env.camera.ColoredShape;
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
 *
 * <p>Reading the sensors is independent per robot (each reads the world, which does not change
 * meanwhile, and draws noise from its own stream), so it runs through the {@link Parallel} loop
 * the simulation is given; the results are the same with any loop. Commands and motion run on the
 * calling thread, in the world file's order.
 *
 * <p>Before step 1 the sensors are read when first asked for (a robot's state, a snapshot, or step
 * 1), so that robots replacing their parameters one after another do not make every robot read
 * its sensors again each time: the readings are those of the world as it then is, each robot's
 * noise drawn from the start of its stream.
 */
public final class Simulation {
    private final World world;
    private final long seed;
    private final GeometryClient geometry;
    private final Placement placement;
    /** The robots in the world file's order, and where each name stands in it. */
    private final List<SimRobot> order = new ArrayList<>();
    /** Each robot's start, in {@link #order}: the world's robots, then those spawned during the run. */
    private final List<RobotSpec> starts = new ArrayList<>();
    private final Map<String, Integer> indexes = new HashMap<>();
    /** Before step 1: whose sensors are yet to be read (their noise streams untouched). */
    private boolean[] unread;
    private Parallel parallel = Parallel.SERIAL;
    private final MessageRouter messages;
    private final RunEvents events;
    private final RobotDrawings drawings = new RobotDrawings();
    private long step;
    /** The world's movable objects, and the robots' grippers that hold them. */
    private final Pucks pucks;
    private final Grippers grippers;
    private final CameraScene cameraScene;

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
        this(world, seed, Parallel.SERIAL);
    }

    /**
     * @param world    the world, with its robots at their start poses
     * @param seed     the seed of the run's noise: each robot draws from its own stream, split from
     *                 it in the world file's order
     * @param parallel how to run the work that is independent per robot
     */
    public Simulation(World world, long seed, Parallel parallel) {
        this.world = world;
        this.seed = seed;
        setParallel(parallel);
        List<Polygon> obstacles = new ArrayList<>();
        for (Obstacle o : world.obstacles()) {
            obstacles.add(o.polygon());
        }
        geometry = new GeometryClient(obstacles);
        cameraScene = new CameraScene(world.obstacles());
        placement = new Placement(geometry);
        pucks = new Pucks(world.objects());
        grippers = new Grippers(pucks, geometry);
        SplittableRandom streams = new SplittableRandom(seed);
        for (RobotSpec spec : world.robots()) {
            BodyShape body = RobotSpec.bodyOf(spec.parameters());
            if (indexes.putIfAbsent(spec.name(), order.size()) != null) {
                throw new IllegalArgumentException("world " + world.name() + " names robot '" + spec.name()
                        + "' twice: each robot's name must be its own");
            }
            int id = geometry.addBody(body, new Pose2D(spec.x(), spec.y(), Math.toRadians(spec.th())));
            order.add(newRobot(spec, spec.parameters(), body, id, streams.split()));
            starts.add(spec);
        }
        pucks.place(geometry);
        unread = new boolean[order.size()];
        Arrays.fill(unread, true);
        // the messages' losses draw from a stream of their own, so they do not shift the robots' noise
        messages = new MessageRouter(robotNames(), world.comms(), new SplittableRandom(seed).nextLong() ^ 0x636f6d6d73L);
        events = new RunEvents(world, messages);
    }

    private SimRobot newRobot(RobotSpec spec, RobotParameters p, BodyShape body, int bodyId, RandomGenerator random) {
        SimRobot r = new SimRobot(spec.name(), spec.type(), p, body, bodyId, spec.x(), spec.y(), spec.th(),
                world.noise(), random, world.rules().motorsEnabled());
        r.sweeper = pucks;
        return r;
    }

    /**
     * Chooses how the work that is independent per robot runs from now on; the results are the
     * same with any loop.
     *
     * @param parallel the loop, {@link Parallel#SERIAL} for the calling thread alone
     */
    public void setParallel(Parallel parallel) {
        if (parallel == null) {
            throw new IllegalArgumentException("null was supplied for parallel: use Parallel.SERIAL for one thread");
        }
        this.parallel = parallel;
    }

    /** @return robot {@code i}'s noise stream as it was split from the seed, untouched */
    private SplittableRandom stream(int i) {
        SplittableRandom streams = new SplittableRandom(seed);
        for (int k = 0; k < i; k++) {
            streams.split();
        }
        return streams.split();
    }

    /**
     * Puts a new robot in place {@code i}, as at the start: its noise stream untouched and its
     * sensors still to read.
     */
    private void renew(int i, RobotParameters p, BodyShape body) {
        SimRobot prev = order.get(i);
        RobotSpec spec = starts.get(i);
        SimRobot r = newRobot(spec, p, body, prev.bodyId, unread[i] ? prev.random : stream(i));
        r.connected = prev.connected;
        order.set(i, r);
        unread[i] = true;
    }

    /**
     * Adds a robot the world does not name (an open world's newcomer) at the first of the poses
     * where its body lies inside the world and touches nothing. It draws its noise from the stream
     * split from the seed for its place in the order, so the same joins give the same run.
     *
     * @param name   its name, not yet in the world
     * @param type   the robot API its program is written against
     * @param params its parameters, which give its body
     * @param poses  where it may be placed, in order; headings in radians
     * @return the pose it was placed at
     * @throws IllegalArgumentException if the name is taken or no pose is free, saying so
     */
    public Pose2D spawn(String name, String type, RobotParameters params, List<Pose2D> poses) {
        if (indexes.containsKey(name)) {
            throw new IllegalArgumentException("world " + world.name() + " already has a robot named '" + name + "'");
        }
        if (poses.isEmpty()) {
            throw new IllegalArgumentException("world " + world.name() + " has no <spawn> pose for robot " + name);
        }
        BodyShape body = RobotSpec.bodyOf(params);
        for (Pose2D pose : poses) {
            if (placement.inside(body, pose, world.bounds()) && !geometry.overlaps(body, pose, -1)) {
                int i = order.size();
                RobotSpec spec = new RobotSpec(name, type, pose.x(), pose.y(), Math.toDegrees(pose.th()), null, params, 0);
                order.add(newRobot(spec, params, body, geometry.addBody(body, pose), stream(i)));
                starts.add(spec);
                indexes.put(name, i);
                unread = Arrays.copyOf(unread, order.size());
                unread[i] = true;
                messages.addRobot(name);
                return pose;
            }
        }
        throw new IllegalArgumentException("every <spawn> pose of world " + world.name() + " (" + poses.size()
                + ") is taken or too tight for robot " + name + "'s body of " + params.robotLength() + " x "
                + params.robotWidth() + " mm");
    }

    /**
     * @param name a robot
     * @return the robot API its program is written against, as the world or its hello named it
     */
    public String type(String name) {
        return robot(name).type;
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
        BodyShape body = RobotSpec.bodyOf(params);
        if (geometry.overlaps(body, r.pose(), r.bodyId)) {
            throw new IllegalArgumentException("robot " + name + " with its body of " + params.robotLength()
                    + " x " + params.robotWidth() + " mm overlaps something at its start pose");
        }
        Envelope before = geometry.bodyPolygon(r.bodyId).getEnvelopeInternal();
        geometry.replaceBody(r.bodyId, body);
        Envelope after = geometry.bodyPolygon(r.bodyId).getEnvelopeInternal();
        int i = indexes.get(name);
        renew(i, params, body);
        // the robots that could see the body, as it was or as it is, read their sensors again
        for (int j = 0; j < order.size(); j++) {
            SimRobot other = order.get(j);
            if (!unread[j] && (other.sees(before) || other.sees(after))) {
                renew(j, other.params, other.body);
            }
        }
    }

    /** Before step 1: reads the sensors of the robots not yet read. */
    private void readUnread() {
        if (step == 0) {
            parallel.forEach(order.size(), this::readIfUnread);
        }
    }

    /** Before step 1: reads robot {@code i}'s sensors if they have not been read. */
    private void readIfUnread(int i) {
        if (unread[i]) {
            SimRobot r = order.get(i);
            r.readSensors(geometry, world.heat(), timeMs(), 0, () -> cameraScene.now(order, geometry, pucks));
            unread[i] = false;
        }
    }

    /**
     * Advances the world one step.
     *
     * @param commands each robot's commands for this step, by name; robots absent keep their commands
     */
    public void step(Map<String, List<Command>> commands) {
        readUnread();
        long current = step + 1;
        events.newStep();
        for (SimRobot r : order) {
            List<Command> cs = commands.get(r.name);
            if (cs != null) {
                for (Command c : cs) {
                    apply(r, c, current);
                }
            }
        }
        double dt = world.stepMs() / 1000.0;
        for (SimRobot r : order) {
            r.move(geometry, dt);
        }
        grippers.step(order, dt);
        step = current;
        drawings.stepEnded();
        readSensors();
        messages.deliver(step, new RobotPositions(this::robot, geometry), RobotPositions.connected(order));
    }

    /** Hands a command to what carries out its group, in the order the robot sent it. */
    private void apply(SimRobot r, Command c, long current) {
        if (c instanceof Command.Motion m) {
            String refusal = r.command(m);
            if (refusal != null && !refusal.isEmpty()) {
                messages.error(r.name, "step " + current + ": " + refusal);
            }
        } else if (c instanceof Command.SensorSetting s) {
            r.sensors().configure(s);
        } else if (c instanceof Command.Messaging m) {
            messages.take(current, r.name, m);
        } else if (c instanceof Command.Draw d) {
            String refusal = drawings.draw(r.name, d, current);
            if (refusal != null) {
                messages.error(r.name, refusal);
            }
        } else if (c instanceof Command.RunEvent e) {
            events.take(r, e, current);
        } else if (c instanceof Command.Simulator s) {
            simulator(r, s, current);
        } else if (c instanceof Command.Accessory a) {
            String refusal = grippers.command(r, a, current);
            if (refusal != null) {
                messages.error(r.name, refusal);
            }
        } else {
            throw new IllegalStateException("no handler for the command group of " + c);
        }
    }

    private void simulator(SimRobot r, Command.Simulator c, long current) {
        Pose2D to;
        if (c instanceof Command.SetTruePose p) {
            to = new Pose2D(p.x(), p.y(), Math.toRadians(p.th()));
        } else if (c instanceof Command.ResetToStart) {
            // a robot spawned in an open world starts where it was placed
            RobotSpec spec = starts.get(indexes.get(r.name));
            to = new Pose2D(spec.x(), spec.y(), Math.toRadians(spec.th()));
        } else {
            throw new IllegalStateException("no handler for the simulator command " + c);
        }
        String refusal = placement.place(r, to, c instanceof Command.ResetToStart, " at step " + current);
        if (refusal != null) {
            messages.error(r.name, refusal);
        }
    }

    /**
     * Places a robot at a true pose between steps without changing its odometry, as a robot's own
     * {@link Command.SetTruePose} does within a step (MobileSim's SIM_SET_POSE): its program sees the
     * jump only in its true pose, its sensors read the new place at the next step.
     *
     * @param name the robot
     * @param x    mm
     * @param y    mm
     * @param th   degrees
     * @return why the robot cannot be placed there (the robot then stays where it is), or null once placed
     * @throws IllegalArgumentException if the robot is unknown or a value is not finite
     */
    public String place(String name, double x, double y, double th) {
        SimRobot r = robot(name);
        if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(th)) {
            throw new IllegalArgumentException("robot " + name + " cannot be placed at (" + x + ", " + y + ", " + th
                    + "): a pose is finite");
        }
        return placement.place(r, new Pose2D(x, y, Math.toRadians(th)), false, "");
    }

    /** A robot's report of a find counts when its centre is this near the gold, mm. */
    public static final double GOLD_FOUND_DISTANCE = 1000;

    /** @return the first confirmed find of the gold, or null */
    public Find find() {
        return events.find();
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
        long now = timeMs();
        double dt = world.stepMs() / 1000.0;
        // the scene a camera sees is made once a step, by the first robot whose camera is on
        Supplier<List<ColoredShape>> scene = new Once<>(() -> cameraScene.now(order, geometry, pucks));
        parallel.forEach(order.size(), i -> order.get(i).readSensors(geometry, world.heat(), now, dt, scene));
    }

    /**
     * Stops a robot whose program has left, so it stays where it is as an obstacle.
     *
     * @param name the robot
     */
    public void halt(String name) {
        robot(name).drive(new Command.Stop());
    }

    /** @return the seed of the run's noise */
    public long seed() {
        return seed;
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
        List<String> names = new ArrayList<>(order.size());
        for (SimRobot r : order) {
            names.add(r.name);
        }
        return Collections.unmodifiableList(names);
    }

    /**
     * @param name a robot
     * @return what it knows of itself now
     */
    public RobotState state(String name) {
        SimRobot r = robot(name);
        readIfUnread(indexes.get(name));
        return r.state(step, timeMs(), messages.delivered(name), messages.errors(name), grippers.state(r));
    }

    /**
     * @param name a robot
     * @return its true pose, distance travelled, collisions, stalls and messages
     */
    public RobotSummary summary(String name) {
        SimRobot r = robot(name);
        Odometry o = r.odometry();
        long[] tally = messages.tally(name);
        return new RobotSummary(r.name, r.x(), r.y(), r.th(), r.distance(), r.collisions(), r.stalled(),
                o.x(), o.y(), o.th(), r.stalls(), tally[0], messages.lost(name), tally[1]);
    }

    /**
     * The metrics the robots reported ({@link Command.ReportMetric}): for each, the last value of
     * each name.
     *
     * @return robot name to metric name to value: every robot in the world's order (an empty map for
     *         one that reported none), each robot's metrics in the order it first reported them
     */
    public Map<String, Map<String, Double>> metrics() {
        Map<String, Map<String, Double>> all = new LinkedHashMap<>();
        for (SimRobot r : order) {
            all.put(r.name, Collections.unmodifiableMap(new LinkedHashMap<>(events.metrics(r.name))));
        }
        return Collections.unmodifiableMap(all);
    }

    /**
     * @return the first robot's request to end the run ({@link Command.EndRun}): the robot, the step
     *         it came in and its reason; or null if none came
     */
    public Snapshot.EndRequest endRequest() {
        return events.endRequest();
    }

    /**
     * @param name a robot
     * @return the messages it sent that the CommunicationsSystem accepted, and those delivered to it,
     *         since the run started
     */
    public long[] messageCounts(String name) {
        robot(name);
        return messages.tally(name);
    }

    /**
     * @param name a robot
     * @return the parameters its body and sensors have now
     */
    public RobotParameters parameters(String name) {
        return robot(name).params;
    }

    /**
     * Marks a robot's program as connected or not, for viewers. A program that connects finds a
     * Pioneer's motors as the world says ({@code <world motors=...>}, disabled by default); one that
     * leaves loses its drawings, cleared in the next step's snapshot.
     *
     * @param name      the robot
     * @param connected whether its program is connected
     */
    public void setConnected(String name, boolean connected) {
        SimRobot r = robot(name);
        r.connected = connected;
        if (connected) {
            r.motorsAtConnect(world.rules().motorsEnabled());
        } else {
            drawings.drop(name);
        }
    }

    /**
     * @return the moving parts of the world now, for viewers, with the drawings that changed, the
     *         metrics reported and the request to end the run that came in the last step
     */
    public Snapshot snapshot() {
        readUnread();
        Snapshot.EndRequest end = events.endRequest();
        return new Snapshot(step, timeMs(), Views.robots(order), messages.sentLastStep(), events.said())
                .withObjects(pucks.views(grippers::lifted)).withDrawings(drawings.changed())
                .withRunEvents(events.reported(), end != null && end.step() == step ? end : null);
    }

    /**
     * Every robot's drawings now, for a viewer that has not seen them: one that attaches, or one
     * sent the world again (which forgets the drawings it had).
     *
     * @return each robot's layers, robot by robot in the order they first drew
     */
    public List<Snapshot.Drawing> drawings() {
        return drawings.all();
    }

    /** @return the static world, with every robot in it now, for viewers */
    public WorldDescription description() {
        return Views.description(world, order).withObjects(Views.objects(world));
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
        Integer i = indexes.get(name);
        if (i == null) {
            throw new IllegalArgumentException("no robot named '" + name + "' in world " + world.name());
        }
        return order.get(i);
    }
}
