package robosim.viewer.draw;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;

/**
 * Which robots have gone from the run (left, dropped, lost, or removed by a control client) after
 * the snapshots seen so far, as opposed to robots whose programs have not connected yet: both are
 * "not connected" in a snapshot, and only the snapshot of the step a robot went says why. A follower
 * of a run folds the snapshots here and hands the renderer a snapshot that still names every robot
 * gone ({@link #over}), as it carries the robots' drawings with {@link Drawings}. A robot that joins
 * again is no longer gone. Plain data, fed by one thread, like {@link Trails}.
 */
public final class Departures {
    /** How a snapshot's events name a robot's departure. */
    public static final Set<String> KINDS = Set.of("left", "dropped", "lost");

    /** The departure of each robot gone now, in the order they went. */
    private final Map<String, Snapshot.Event> gone = new LinkedHashMap<>();
    /** The robots seen connected, so that one seen to go without an event still counts as gone. */
    private final Set<String> seen = new HashSet<>();

    /**
     * Takes the next snapshot's joins, departures and connections.
     *
     * @param snapshot the next snapshot
     */
    public void add(Snapshot snapshot) {
        for (Snapshot.Event e : snapshot.events()) {
            if (e.robot() == null) {
                continue;
            }
            if (KINDS.contains(e.what())) {
                gone.remove(e.robot());
                gone.put(e.robot(), e);
            } else {
                gone.remove(e.robot());
            }
        }
        for (RobotView r : snapshot.robots()) {
            if (r.name() == null) {
                continue;
            }
            if (r.connected()) {
                seen.add(r.name());
                gone.remove(r.name());
            } else if (seen.contains(r.name()) && !gone.containsKey(r.name())) {
                gone.put(r.name(), new Snapshot.Event(r.name(), "left", snapshot.step(), ""));
            }
        }
    }

    /** Forgets everything, as when a world arrives or a replay jumps back. */
    public void clear() {
        gone.clear();
        seen.clear();
    }

    /**
     * @param robot a robot's name
     * @return whether it has gone and not joined again
     */
    public boolean gone(String robot) {
        return gone.containsKey(robot);
    }

    /**
     * @param snapshot the latest snapshot, already {@linkplain #add added}
     * @return it with its events followed by the departure of every robot gone before it, so that
     *         {@link #gone(Snapshot, RobotView)} tells them from robots not connected yet; itself when
     *         none went before it
     */
    public Snapshot over(Snapshot snapshot) {
        List<Snapshot.Event> events = new ArrayList<>(snapshot.events());
        for (Snapshot.Event e : gone.values()) {
            if (!events.contains(e)) {
                events.add(e);
            }
        }
        return events.size() == snapshot.events().size() ? snapshot : snapshot.withEvents(events);
    }

    /**
     * How the renderers tell a robot gone from one not connected yet: it is not connected, and the
     * snapshot's events name it as gone after any join.
     *
     * @param snapshot a snapshot, possibly {@linkplain #over carrying earlier departures}
     * @param robot    one of its robots
     * @return whether the robot has gone from the run
     */
    public static boolean gone(Snapshot snapshot, RobotView robot) {
        if (robot.connected() || robot.name() == null) {
            return false;
        }
        boolean gone = false;
        for (Snapshot.Event e : snapshot.events()) {
            if (robot.name().equals(e.robot())) {
                gone = KINDS.contains(e.what());
            }
        }
        return gone;
    }
}
