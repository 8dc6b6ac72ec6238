package robosim.panel.model;

import java.util.HashSet;
import java.util.Set;
import robosim.protocol.RunStatus;

/**
 * The robots seen connected in the run the statuses describe, so that the table tells a robot that
 * has gone from one that never came. A status of another world, or of an earlier step than the last
 * (a run restarted), starts a new run: the robots seen before are forgotten.
 */
public final class SeenRobots {
    private final Set<String> seen = new HashSet<>();
    private String world;
    private long step = -1;

    /**
     * @param status the next status
     * @return the robots seen connected in its run, this status included (read-only)
     */
    public Set<String> update(RunStatus status) {
        if (!status.world().equals(world) || status.step() < step) {
            seen.clear();
        }
        world = status.world();
        step = status.step();
        for (RunStatus.RobotStatus r : status.robots()) {
            if (r.connected()) {
                seen.add(r.name());
            }
        }
        return Set.copyOf(seen);
    }
}
