package robosim.it;

import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import robosim.protocol.Bye;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.Snapshot;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldDescription;
import robosim.cli.Background;

/** A viewer for tests: attaches and keeps the world and the latest snapshot of each step until the run ends. */
final class SnapshotCollector {
    private final CompletableFuture<Void> done;
    private volatile WorldDescription world;
    private final List<Snapshot> snapshots = new ArrayList<>();

    SnapshotCollector(int port) throws Exception {
        Socket s = new Socket("127.0.0.1", port);
        s.setSoTimeout(120_000);
        MessageCodec codec = new MessageCodec();
        new FrameWriter(s.getOutputStream(), codec).write(new ViewerHello("test"));
        done = Background.run("snapshot-collector", () -> {
            try (s) {
                FrameReader r = new FrameReader(s.getInputStream(), codec, 1 << 24);
                Message m;
                while ((m = r.read()) != null && !(m instanceof Bye)) {
                    if (m instanceof WorldDescription w) {
                        world = w;
                    } else if (m instanceof Snapshot f) {
                        synchronized (snapshots) {
                            // step 0 comes again as the run starts: the later one is the start
                            if (!snapshots.isEmpty() && snapshots.get(snapshots.size() - 1).step() == f.step()) {
                                snapshots.remove(snapshots.size() - 1);
                            }
                            snapshots.add(f);
                        }
                    }
                }
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        });
    }

    WorldDescription world() throws Exception {
        done.get(60, TimeUnit.SECONDS);
        return world;
    }

    List<Snapshot> snapshots() throws Exception {
        done.get(60, TimeUnit.SECONDS);
        synchronized (snapshots) {
            return List.copyOf(snapshots);
        }
    }
}
