package robosim.it;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.SnapshotListener;

/**
 * Keys for a program's {@code ArKeyHandler}, pressed at given steps of a lockstep run: a standard
 * input that gives the keys of step N once the Environment has run step N, and holds the run there
 * until the key handler's reader has taken every one of them, so the robot's next cycle handles them
 * all. The same keys at the same steps make the same run. Closing it ends the input.
 */
final class SteppedKeys extends InputStream implements SnapshotListener {
    private static final int END = -1;
    private final Map<Long, String> keys;
    private final BlockingQueue<Integer> pressed = new LinkedBlockingQueue<>();
    /** A permit each time the reader asks for a byte: the bytes before have been taken. */
    private final Semaphore reading = new Semaphore(0);

    /** @param keys the keys pressed after each step, by step */
    SteppedKeys(Map<Long, String> keys) {
        this.keys = new TreeMap<>(keys);
    }

    @Override
    public int read() {
        reading.release();
        try {
            return pressed.take();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return END;
        }
    }

    @Override
    public void world(WorldDescription world) {
    }

    @Override
    public void snapshot(Snapshot snapshot) {
        String now = keys.get(snapshot.step());
        if (now == null) {
            return;
        }
        try {
            for (byte b : now.getBytes(StandardCharsets.ISO_8859_1)) {
                press(b & 0xff);
            }
            // the reader asks again only once it has queued the last key for the robot's cycle
            if (!reading.tryAcquire(10, TimeUnit.SECONDS)) {
                throw new IllegalStateException("the key handler did not take the keys of step " + snapshot.step());
            }
            reading.release();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void press(int key) throws InterruptedException {
        if (!reading.tryAcquire(10, TimeUnit.SECONDS)) {
            throw new IllegalStateException("no key handler reads the keys (key " + key + ")");
        }
        pressed.add(key);
    }

    @Override
    public void close() {
        pressed.add(END);
    }
}
