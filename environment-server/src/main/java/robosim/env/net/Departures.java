package robosim.env.net;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import robosim.protocol.Snapshot;

/**
 * The robots that went, and came, during the run, as the session rules see them. Only the first
 * way a robot goes counts until it comes back (a robot lost is then dropped from the run too), and
 * only once the run has started: before that a robot may leave and come back unrecorded.
 */
final class Departures {
    private final List<Departure> gone = new ArrayList<>();
    private final List<Join> joins = new ArrayList<>();
    private final Set<String> away = new HashSet<>();
    /** The joins and departures not yet in a snapshot. */
    private final List<Snapshot.Event> events = new ArrayList<>();
    private boolean started;

    /** A new run replaces the one recorded: everything is forgotten, and the new run has not started. */
    void reset() {
        gone.clear();
        joins.clear();
        away.clear();
        events.clear();
        started = false;
    }

    /** The run has started: from now every departure and join is recorded. */
    void start() {
        started = true;
    }

    /** @return whether the run has started */
    boolean started() {
        return started;
    }

    /**
     * Marks a robot gone, unless it already is or the run has not started.
     *
     * @param robot  the robot
     * @param kind   how it went
     * @param step   the step open, or the last step run
     * @param reason why
     */
    void mark(String robot, Departure.Kind kind, long step, String reason) {
        if (started && away.add(robot)) {
            gone.add(new Departure(robot, kind, step, reason));
            events.add(new Snapshot.Event(robot, kind.word(), step, reason));
        }
    }

    /**
     * Marks a robot joined after the run started.
     *
     * @param robot  the robot
     * @param spawned whether the world does not name it (an open world's newcomer)
     * @param step   the first step it takes part in
     * @return the join recorded, or null before the run starts
     */
    Join joined(String robot, boolean spawned, long step) {
        if (!started) {
            return null;
        }
        Join.Kind kind = spawned ? Join.Kind.SPAWNED : away.remove(robot) ? Join.Kind.REJOINED : Join.Kind.LATE;
        Join j = new Join(robot, kind, step);
        joins.add(j);
        events.add(new Snapshot.Event(robot, kind.word(), step, ""));
        return j;
    }

    /** @return the joins and departures since the last call, for the next snapshot, in the order they came */
    List<Snapshot.Event> takeEvents() {
        List<Snapshot.Event> taken = List.copyOf(events);
        events.clear();
        return taken;
    }

    /** @return the robots gone, in the order they went; a robot that came back may be in it more than once */
    List<Departure> list() {
        return new ArrayList<>(gone);
    }

    /** @return the robots that joined after the run started, in the order they came */
    List<Join> joins() {
        return new ArrayList<>(joins);
    }
}
