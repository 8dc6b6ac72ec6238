package robosim.comms;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.TreeMap;
import robosim.protocol.Command;
import robosim.protocol.MessageDelivery;

/**
 * The CommunicationsSystem: carries messages between robots point to point, to groups (multicast)
 * and to everyone (broadcast), by the rules of its {@link CommsSettings}. Pure and deterministic:
 * messages are delivered at step boundaries in a fixed order (due step, then the order they were
 * sent in, then the recipients in the world's robot order), and losses come from the run's seed.
 */
public final class CommunicationsSystem {
    private final List<String> robots;
    private final Map<String, Set<String>> groups = new TreeMap<>();
    private final List<InFlight> inFlight = new ArrayList<>();
    /** Each sender's copies dropped on the way to a recipient, since the system was made. */
    private final Map<String, Long> lost = new HashMap<>();
    private final SplittableRandom random;
    private CommsSettings settings;

    private record InFlight(long due, long sentStep, String from, Command.SendMessage message) { }

    /**
     * @param robots   every robot of the world, in the world's order
     * @param settings how messages travel
     * @param seed     the seed of the losses
     */
    public CommunicationsSystem(List<String> robots, CommsSettings settings, long seed) {
        this.robots = new ArrayList<>(robots);
        this.settings = settings;
        this.random = new SplittableRandom(seed);
    }

    /**
     * Adds a robot that joined the world during the run (an open world's newcomer), after the others.
     *
     * @param robot its name, not yet in the world
     * @throws IllegalArgumentException if a robot of that name is already in the world
     */
    public void addRobot(String robot) {
        if (robots.contains(robot)) {
            throw new IllegalArgumentException("robot '" + robot + "' is already in the world: each name is its own");
        }
        robots.add(robot);
    }

    /** @return how messages travel now */
    public CommsSettings settings() {
        return settings;
    }

    /**
     * Changes how messages travel, from now on: range, walls and loss apply to messages delivered
     * from the next delivery on, latency and size to messages sent from now on.
     *
     * @param settings the new settings
     */
    public void setSettings(CommsSettings settings) {
        this.settings = settings;
    }

    /**
     * @param robot a robot
     * @param group a group name; joining makes the group known
     */
    public void join(String robot, String group) {
        groups.computeIfAbsent(group, g -> new LinkedHashSet<>()).add(robot);
    }

    /**
     * @param robot a robot
     * @param group a group it may belong to
     */
    public void leave(String robot, String group) {
        Set<String> members = groups.get(group);
        if (members != null) {
            members.remove(robot);
            if (members.isEmpty()) {
                groups.remove(group);
            }
        }
    }

    /**
     * @param group a group
     * @return its members, in the world's robot order
     */
    public List<String> members(String group) {
        Set<String> m = groups.getOrDefault(group, Set.of());
        return robots.stream().filter(m::contains).toList();
    }

    /**
     * Accepts a message for delivery after the current latency.
     *
     * @param step    the step in which it is sent
     * @param from    the sender
     * @param message the message
     * @return what is wrong with it (it is then not sent), or null
     */
    public String submit(long step, String from, Command.SendMessage message) {
        // an unknown sender has no position, so delivery would fail for every message of the step
        if (from == null || !robots.contains(from)) {
            return "message " + message.id() + " is from '" + from + "', but there is no robot of that name";
        }
        int bytes = message.body().getBytes(StandardCharsets.UTF_8).length;
        if (bytes > settings.maxMessageBytes()) {
            return "message " + message.id() + " of " + bytes + " bytes is over the limit of "
                    + settings.maxMessageBytes() + " bytes";
        }
        switch (message.mode()) {
            case ROBOT -> {
                if (!robots.contains(message.to())) {
                    return "message " + message.id() + " is addressed to '" + message.to()
                            + "', but there is no robot of that name";
                }
            }
            case GROUP -> {
                if (!groups.containsKey(message.to())) {
                    return "message " + message.id() + " is addressed to group '" + message.to()
                            + "', which no robot has joined";
                }
            }
            case ALL -> { }
        }
        inFlight.add(new InFlight(step + settings.latencySteps() - 1, step, from, message));
        return null;
    }

    /**
     * Delivers every message due by the end of {@code step}.
     *
     * @param step      the step that has just been simulated
     * @param positions where the robots are and what lies between them
     * @param connected the robots whose programs are connected (the others receive nothing)
     * @return each recipient's deliveries, in order; robots with none are absent
     */
    public Map<String, List<MessageDelivery>> deliver(long step, Positions positions, Set<String> connected) {
        Map<String, List<MessageDelivery>> out = new LinkedHashMap<>();
        Iterator<InFlight> it = inFlight.iterator();
        while (it.hasNext()) {
            InFlight f = it.next();
            if (f.due() > step) {
                continue;
            }
            it.remove();
            Command.SendMessage m = f.message();
            String to = m.mode() == Command.Addressing.ALL ? "*" : m.to();
            for (String r : recipients(f)) {
                if (!connected.contains(r)) {
                    // a robot without a program receives nothing: no copy was on its way to be lost
                    continue;
                }
                if (reaches(f.from(), r, positions)) {
                    out.computeIfAbsent(r, k -> new ArrayList<>())
                            .add(new MessageDelivery(f.from(), m.mode(), to, m.kind(), m.body(), f.sentStep(), m.id()));
                } else {
                    lost.merge(f.from(), 1L, Long::sum);
                }
            }
        }
        return out;
    }

    private List<String> recipients(InFlight f) {
        return switch (f.message().mode()) {
            case ROBOT -> List.of(f.message().to());
            case GROUP -> members(f.message().to()).stream().filter(r -> !r.equals(f.from())).toList();
            case ALL -> robots.stream().filter(r -> !r.equals(f.from())).toList();
        };
    }

    private boolean reaches(String from, String to, Positions positions) {
        if (settings.maxRange() > 0) {
            double[] a = positions.of(from);
            double[] b = positions.of(to);
            if (Math.hypot(a[0] - b[0], a[1] - b[1]) > settings.maxRange()) {
                return false;
            }
        }
        if (settings.wallsBlock() && !positions.clear(from, to)) {
            return false;
        }
        // one draw per message and recipient that got this far, so the stream stays in step
        return settings.lossProbability() == 0 || random.nextDouble() >= settings.lossProbability();
    }

    /**
     * Copies of a robot's messages dropped on the way to a recipient whose program is connected: out
     * of range, behind a wall, or lost by chance; a message to three robots that reaches one counts
     * two. Copies for robots without a program are not counted.
     *
     * @param sender a robot
     * @return its copies dropped since the system was made
     */
    public long lost(String sender) {
        return lost.getOrDefault(sender, 0L);
    }

    /** @return messages sent and not yet delivered */
    public int inFlight() {
        return inFlight.size();
    }
}
