package robosim.it;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.SnapshotListener;
import robosim.protocol.recording.RecordingWriter;
import robosim.viewer.draw.RenderOptions;
import robosim.viewer.net.ViewerClient;
import robosim.viewer.net.ViewerOptions;
import robosim.viewer.net.ViewerSummary;
import robosim.cli.Background;

/**
 * A deterministic run for the recording tests, all in this JVM: the Environment on the small maze
 * recording every step, two wander robots as threads, and optionally a live viewer attached before
 * the robots connect. Every wait is bounded; every thread ends with the run.
 */
final class RecordedRun {
    /** The drawing both the live viewer and the replays use. */
    static final RenderOptions RENDER = new RenderOptions(480, true, true);

    private RecordedRun() {
    }

    /**
     * Runs the maze for some steps.
     *
     * @param steps     steps to run
     * @param recording where the Environment records, with sensors
     * @param viewer    what a live viewer passes the run to, or none for no viewer
     * @return the Environment's report
     */
    static RunReport run(int steps, Path recording, List<SnapshotListener> viewer) throws Exception {
        ServerOptions options = ServerOptions.loopback().withMaxSteps(steps).withWaitViewers(viewer.isEmpty() ? 0 : 1);
        try (LocalEnvironment env = new LocalEnvironment(LocalEnvironment.shipped("small-maze.xml"), 1, options,
                RecordingWriter.create(recording, true))) {
            CompletableFuture<Void> attached = new CompletableFuture<>();
            List<SnapshotListener> listeners = new ArrayList<>(viewer);
            listeners.add(new SnapshotListener() {
                @Override
                public void world(WorldDescription world) {
                    attached.complete(null);
                }

                @Override
                public void snapshot(Snapshot snapshot) {
                }
            });
            CompletableFuture<ViewerSummary> live = viewer.isEmpty() ? CompletableFuture.completedFuture(null)
                    : Background.supply("live viewer", () -> {
                        try {
                            ViewerOptions o = ViewerOptions.of("127.0.0.1", env.viewerPort()).withName("live")
                                    .withReadTimeout(Duration.ofSeconds(60));
                            return new ViewerClient(o, listeners).run();
                        } catch (Exception e) {
                            throw new IllegalStateException(e);
                        }
                    });
            if (!viewer.isEmpty()) {
                attached.get(30, TimeUnit.SECONDS); // the viewer sees step 0 before the robots connect
            }
            List<Thread> robots = env.wanderers();
            RunReport r = env.await();
            live.get(60, TimeUnit.SECONDS);
            for (Thread t : robots) {
                t.join(10_000);
            }
            return r;
        }
    }
}
