package robosim.env.core;

import java.util.ArrayList;
import java.util.List;
import robosim.env.world.HeatSource;
import robosim.env.world.World;
import robosim.protocol.Command;
import robosim.protocol.Snapshot;

/**
 * The run's log, part of {@link Simulation}: what robots said in the step under way, and the first
 * confirmed find of the world's gold (a report counts within {@link Simulation#GOLD_FOUND_DISTANCE}
 * of it; any other is answered with an error the robot reads next).
 */
final class RunEvents {
    private final World world;
    private final MessageRouter messages;
    private final List<Snapshot.Said> said = new ArrayList<>();
    private Find find;

    RunEvents(World world, MessageRouter messages) {
        this.world = world;
        this.messages = messages;
    }

    /** A step begins: what was said in the one before is forgotten. */
    void newStep() {
        said.clear();
    }

    /** Takes a robot's run event, in the order it sent it. */
    void take(SimRobot r, Command.RunEvent e, long current) {
        if (e instanceof Command.Say say) {
            said.add(new Snapshot.Said(r.name, say.text()));
        } else if (e instanceof Command.ReportFound found) {
            reportFound(r, found.object(), current);
        } else {
            throw new IllegalStateException("no handler for the run event " + e);
        }
    }

    private void reportFound(SimRobot r, String object, long current) {
        HeatSource gold = world.gold();
        if (!"gold".equals(object) || gold == null) {
            messages.error(r.name, "robot " + r.name + " reported finding '" + object + "', but world "
                    + world.name() + " has no " + object);
            return;
        }
        double d = Math.hypot(r.x() - gold.x(), r.y() - gold.y());
        if (d > Simulation.GOLD_FOUND_DISTANCE) {
            messages.error(r.name, "robot " + r.name + " reported the gold at step " + current + " but is "
                    + Math.round(d) + " mm from it; a find counts within " + Math.round(Simulation.GOLD_FOUND_DISTANCE)
                    + " mm");
        } else if (find == null) {
            find = new Find(r.name, current, d);
        }
    }

    /** @return what robots said in the last step, in order */
    List<Snapshot.Said> said() {
        return said;
    }

    /** @return the first confirmed find of the gold, or null */
    Find find() {
        return find;
    }
}
