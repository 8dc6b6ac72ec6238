package robosim.env.net;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import robosim.env.threads.PooledParallel;
import robosim.env.core.Simulation;
import robosim.protocol.FrameWriter;
import robosim.protocol.KeepAlive;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.RobotState;
import robosim.protocol.TimeStep;
import robosim.protocol.TimeSteps;

/**
 * What the step loop sends the robots, part of {@link EnvironmentServer}: each step's time step and
 * state, and a keep-alive when they have heard nothing for a while.
 */
final class TimeStepSender {
    /** Robots whose states share one {@link TimeSteps} frame. */
    static final int ROBOTS_PER_FRAME = 100;
    /** How long robots may hear nothing from the Environment before it sends them a {@link KeepAlive}, ms. */
    static final long KEEP_ALIVE_MS = 1_000;

    private final MessageCodec codec;
    private final PooledParallel workers;
    private long sentToRobotsNanos = System.nanoTime();

    TimeStepSender(MessageCodec codec, PooledParallel workers) {
        this.codec = codec;
        this.workers = workers;
    }

    /**
     * Opens the step for every robot: a {@link TimeStep} to each robot on a connection of its own,
     * {@link TimeSteps} to each shared link for its robots, {@value #ROBOTS_PER_FRAME} robots a
     * frame (so that frames stay far under the size limit, are encoded side by side, and the link's
     * first robots start while the rest are on their way). The states are read in the robots'
     * order; the frames are encoded on the worker threads.
     */
    void send(Simulation sim, Map<String, Connection> robots, long current) {
        long timeMs = sim.timeMs();
        List<Connection> to = new ArrayList<>();
        List<Message> steps = new ArrayList<>();
        Map<Connection, List<TimeSteps.ForRobot>> links = new LinkedHashMap<>();
        for (Map.Entry<String, Connection> r : robots.entrySet()) {
            Connection c = r.getValue();
            RobotState state = sim.state(r.getKey());
            if (c.isLink()) {
                links.computeIfAbsent(c, k -> new ArrayList<>()).add(new TimeSteps.ForRobot(r.getKey(), state));
            } else {
                to.add(c);
                steps.add(new TimeStep(current, timeMs, state));
            }
        }
        for (Map.Entry<Connection, List<TimeSteps.ForRobot>> link : links.entrySet()) {
            List<TimeSteps.ForRobot> linked = link.getValue();
            for (int from = 0; from < linked.size(); from += ROBOTS_PER_FRAME) {
                to.add(link.getKey());
                steps.add(new TimeSteps(current, timeMs, linked.subList(from,
                        Math.min(linked.size(), from + ROBOTS_PER_FRAME))));
            }
        }
        ByteBuffer[] frames = new ByteBuffer[steps.size()];
        // a frame of a link's robots is worth a worker's wake-up on its own; an in-process link takes
        // the message itself, never encoded
        workers.forEach(frames.length, links.isEmpty() ? PooledParallel.MIN_CHUNK : 1,
                i -> frames[i] = to.get(i).isInProcess() ? null : FrameWriter.frame(codec, steps.get(i)));
        for (int i = 0; i < frames.length; i++) {
            to.get(i).send(steps.get(i), frames[i]);
        }
        sentToRobotsNanos = System.nanoTime();
    }

    /**
     * Sends a {@link KeepAlive} to every robot connection and shared link that has said hello, once
     * robots have been sent nothing for {@link #KEEP_ALIVE_MS}: before the first step while other
     * robots are still connecting, while a slow robot holds a step up, and while the run is paused.
     * A robot that hears nothing, neither a step nor a keep-alive, for its lost time declares the
     * Environment lost.
     */
    void keepAlive(long step, Iterable<Connection> connections) {
        long now = System.nanoTime();
        if (now - sentToRobotsNanos < TimeUnit.MILLISECONDS.toNanos(KEEP_ALIVE_MS)) {
            return;
        }
        sentToRobotsNanos = now;
        KeepAlive keepAlive = new KeepAlive(step);
        ByteBuffer frame = FrameWriter.frame(codec, keepAlive);
        for (Connection c : connections) {
            if (c.kind == Connection.Kind.ROBOT && (c.isLink() || c.name() != null)) {
                c.send(keepAlive, frame.duplicate());
            }
        }
    }
}
