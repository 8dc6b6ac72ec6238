package robosim.viewer.draw;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robosim.protocol.Snapshot;

/**
 * The robots' drawings as they are after the snapshots seen so far: a snapshot carries only the
 * layers that changed in its step (or, after a world, all of them), so a follower of a run folds
 * them forward here and hands the renderer a snapshot that carries them all ({@link #over}). A
 * layer sent without figures is cleared. Plain data, fed by one thread, like {@link Trails}.
 */
public final class Drawings {
    /** By robot and layer, in the order they were first drawn. */
    private final Map<String, Snapshot.Drawing> layers = new LinkedHashMap<>();

    /**
     * Takes the layers a snapshot says changed.
     *
     * @param snapshot the next snapshot
     */
    public void add(Snapshot snapshot) {
        for (Snapshot.Drawing d : snapshot.drawings()) {
            String key = d.robot() + '\n' + d.layer();
            if (d.figures().isEmpty()) {
                layers.remove(key);
            } else {
                layers.put(key, d);
            }
        }
    }

    /** Forgets every drawing, as when a world arrives (the snapshot after it carries them all). */
    public void clear() {
        layers.clear();
    }

    /** @return every robot's layers now, in the order they were first drawn */
    public List<Snapshot.Drawing> all() {
        return new ArrayList<>(layers.values());
    }

    /**
     * @param snapshot the latest snapshot, already {@linkplain #add added}
     * @return it carrying every current drawing instead of its step's changes alone; itself when
     *         there are none either way
     */
    public Snapshot over(Snapshot snapshot) {
        if (layers.isEmpty() && snapshot.drawings().isEmpty()) {
            return snapshot;
        }
        return snapshot.withDrawings(all());
    }
}
