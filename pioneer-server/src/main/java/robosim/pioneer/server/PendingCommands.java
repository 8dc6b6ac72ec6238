package robosim.pioneer.server;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robosim.protocol.Command;

/**
 * The commands an ARIA client has given since its robot's last step, waiting for the next: the
 * latest of each kind, in the order of their latest arrival, as a Pioneer's firmware keeps one
 * setpoint of each kind between two of its cycles. So a client that streams commands while the run
 * waits for its other robots (or is paused) leaves a handful, not a pile, and they take effect at
 * the robot's next step in the order the client meant them: ENABLE 1 then VEL 200 moves the robot,
 * VEL 200 then STOP stops it. Each drive limit ({@link Command.SetDriveLimit}) is a kind of its own, and so is each gripper
 * operation ({@link Command.Gripper}'s code).
 * Safe to use from the client's thread and the robot's.
 */
final class PendingCommands {
    private final Map<Object, Command> latest = new LinkedHashMap<>();

    /**
     * Keeps a command in place of the last one of its kind, after every other kind waiting.
     *
     * @param c the command
     */
    synchronized void add(Command c) {
        Object kind = kind(c);
        latest.remove(kind);
        latest.put(kind, c);
    }

    /** @return the commands waiting, in order; none wait after */
    synchronized List<Command> drain() {
        List<Command> out = new ArrayList<>(latest.values());
        latest.clear();
        return out;
    }

    /** Forgets the commands waiting. */
    synchronized void clear() {
        latest.clear();
    }

    /** @return how many commands wait */
    synchronized int size() {
        return latest.size();
    }

    private static Object kind(Command c) {
        if (c instanceof Command.Gripper g) {
            return "gripper " + g.op(); // the paddles and the lift are commanded apart: LIFT_UP does not undo GRIP_OPEN
        }
        return c instanceof Command.SetDriveLimit d ? d.limit() : c.getClass();
    }
}
