package robosim.env.core;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robosim.protocol.Command;
import robosim.protocol.Snapshot;

/**
 * The robots' drawings, part of {@link Simulation}: each robot's layers as it last drew them, and
 * the layers that changed, for the snapshot of the step in which they did. A change made between
 * steps (a robot that leaves loses its drawings) goes into the next step's snapshot.
 */
final class RobotDrawings {
    /** Robot, then layer, in the order they were first drawn. */
    private final Map<String, Map<String, Snapshot.Drawing>> current = new LinkedHashMap<>();
    /** The layers changed since the last step ended, by robot and layer; the last change counts. */
    private Map<String, Snapshot.Drawing> pending = new LinkedHashMap<>();
    private List<Snapshot.Drawing> changed = List.of();

    /**
     * Replaces or clears one of a robot's layers.
     *
     * @param robot   the robot
     * @param draw    its command
     * @param current the step under way, named in a refusal
     * @return why it was refused (a new layer past {@value Command.Draw#MAX_LAYERS}), or null
     */
    String draw(String robot, Command.Draw draw, long current) {
        Map<String, Snapshot.Drawing> layers = this.current.computeIfAbsent(robot, r -> new LinkedHashMap<>());
        String layer = draw.layer();
        if (draw.figures().isEmpty()) {
            if (layers.remove(layer) != null) {
                changed(new Snapshot.Drawing(robot, layer, List.of()));
            }
            return null;
        }
        if (!layers.containsKey(layer) && layers.size() >= Command.Draw.MAX_LAYERS) {
            return "step " + current + ": robot " + robot + " has " + layers.size() + " drawing layers "
                    + layers.keySet() + ", the most a robot may have; layer " + layer
                    + " was not drawn (clear a layer with an empty list first)";
        }
        Snapshot.Drawing d = new Snapshot.Drawing(robot, layer, draw.figures());
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
            for (String layer : layers.keySet()) {
                changed(new Snapshot.Drawing(robot, layer, List.of()));
            }
        }
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
