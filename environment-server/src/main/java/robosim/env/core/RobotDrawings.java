package robosim.env.core;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robosim.protocol.Command;
import robosim.protocol.Figure;
import robosim.protocol.Snapshot;

/**
 * The robots' drawings, part of {@link Simulation}: each robot's layers as it last drew them, and
 * the layers that changed, for the snapshot of the step in which they did. A change made between
 * steps (a robot that leaves loses its drawings) goes into the next step's snapshot.
 *
 * <p>All the robots' layers together hold at most {@value #MAX_NUMBERS} numbers, so that the
 * snapshot a viewer gets when it attaches, which carries them all, stays well inside a viewer's
 * frame limit (4 MiB; a number takes about 11 bytes in Smile).
 */
final class RobotDrawings {
    /** The most numbers all the robots' layers may hold together. */
    static final int MAX_NUMBERS = 200_000;

    /** Robot, then layer, in the order they were first drawn. */
    private final Map<String, Map<String, Snapshot.Drawing>> current = new LinkedHashMap<>();
    /** The layers changed since the last step ended, by robot and layer; the last change counts. */
    private Map<String, Snapshot.Drawing> pending = new LinkedHashMap<>();
    private List<Snapshot.Drawing> changed = List.of();
    /** How many numbers all the layers hold now. */
    private long numbers;

    /**
     * Replaces or clears one of a robot's layers.
     *
     * @param robot   the robot
     * @param draw    its command
     * @param current the step under way, named in a refusal
     * @return why it was refused (a new layer past {@value Command.Draw#MAX_LAYERS}, or more numbers
     *         than all the robots' layers may hold), or null
     */
    String draw(String robot, Command.Draw draw, long current) {
        Map<String, Snapshot.Drawing> layers = this.current.computeIfAbsent(robot, r -> new LinkedHashMap<>());
        String layer = draw.layer();
        if (draw.figures().isEmpty()) {
            Snapshot.Drawing gone = layers.remove(layer);
            if (gone != null) {
                numbers -= count(gone);
                changed(new Snapshot.Drawing(robot, layer, List.of()));
            }
            return null;
        }
        Snapshot.Drawing before = layers.get(layer);
        if (before == null && layers.size() >= Command.Draw.MAX_LAYERS) {
            return "step " + current + ": robot " + robot + " has " + layers.size() + " drawing layers "
                    + layers.keySet() + ", the most a robot may have; layer " + layer
                    + " was not drawn (clear a layer with an empty list first)";
        }
        Snapshot.Drawing d = new Snapshot.Drawing(robot, layer, draw.figures());
        long after = numbers - (before == null ? 0 : count(before)) + count(d);
        if (after > MAX_NUMBERS) {
            return "step " + current + ": robot " + robot + "'s layer " + layer + " of " + count(d)
                    + " numbers would bring the robots' drawings to " + after + " numbers, more than the "
                    + MAX_NUMBERS + " they may hold together; it was not drawn";
        }
        numbers = after;
        layers.put(layer, d);
        changed(d);
        return null;
    }

    /**
     * Clears every layer of a robot that has left.
     *
     * @param robot the robot
     */
    void drop(String robot) {
        Map<String, Snapshot.Drawing> layers = current.remove(robot);
        if (layers != null) {
            for (Snapshot.Drawing d : layers.values()) {
                numbers -= count(d);
                changed(new Snapshot.Drawing(robot, d.layer(), List.of()));
            }
        }
    }

    private static long count(Snapshot.Drawing d) {
        long n = 0;
        for (Figure f : d.figures()) {
            n += f.size();
        }
        return n;
    }

    private void changed(Snapshot.Drawing d) {
        pending.put(d.robot() + '\n' + d.layer(), d);
    }

    /** A step has ended: the changes since the one before are its snapshot's. */
    void stepEnded() {
        changed = List.copyOf(pending.values());
        pending = new LinkedHashMap<>();
    }

    /** @return the layers that changed in the last step, in the order they did */
    List<Snapshot.Drawing> changed() {
        return changed;
    }

    /** @return every layer of every robot now, for a viewer that attaches or a world sent again */
    List<Snapshot.Drawing> all() {
        List<Snapshot.Drawing> all = new ArrayList<>();
        for (Map<String, Snapshot.Drawing> layers : current.values()) {
            all.addAll(layers.values());
        }
        return all;
    }
}
