package robosim.protocol.recording;

import java.io.Closeable;
import java.io.IOException;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;

/**
 * Follows a run as a viewer sees it: the world first, then the snapshot after every step, then the
 * end. The Environment feeds its listeners (a recorder) from its step loop; a viewer feeds its
 * listeners (a window, a recorder, a PNG writer) from the wire.
 *
 * <p>Calls come from one thread, in order: {@link #world} before any {@link #snapshot} (again if the
 * world is reloaded), {@link #end} at most once, and {@link #close} last.
 */
public interface SnapshotListener extends Closeable {
    /**
     * The static world, before the snapshots drawn in it.
     *
     * @param world the world
     * @throws IOException if the listener cannot take it; the feeder then drops the listener
     */
    void world(WorldDescription world) throws IOException;

    /**
     * The moving parts after one step.
     *
     * @param snapshot the snapshot
     * @throws IOException if the listener cannot take it; the feeder then drops the listener
     */
    void snapshot(Snapshot snapshot) throws IOException;

    /**
     * The run ended in order.
     *
     * @param reason why, as the Environment says it
     * @throws IOException if the listener cannot take it
     */
    default void end(String reason) throws IOException {
    }

    /**
     * Releases what the listener holds; no more calls follow.
     *
     * @throws IOException if releasing fails
     */
    @Override
    default void close() throws IOException {
    }
}
