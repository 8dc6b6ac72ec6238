package robosim.panel.net;

import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import robosim.panel.model.Reachability;
import robosim.protocol.RunSecret;
import robosim.protocol.recording.SnapshotListener;
import robosim.viewer.net.ViewerClient;
import robosim.viewer.net.ViewerException;
import robosim.viewer.net.ViewerOptions;
import robosim.viewer.net.ViewerSummary;

/**
 * The panel's live view of its Environment: a viewer attached to the viewer port that attaches
 * again whenever it cannot attach or its run ends, until stopped, so that a panel attached before
 * its Environment starts (or writes its secret) shows the run once it is there, and shows an
 * Environment restarted on the same port. Each attempt is a new {@link ViewerClient}, which looks
 * the run secret up again. The waits between attempts and what is logged follow
 * {@link Reachability}: one line per change, never one per attempt.
 */
public final class PanelView {
    /** How soon a failed attempt is first tried again, ms; later waits grow to {@link Reachability#MAX_RETRY_MS}. */
    static final long FIRST_RETRY_MS = 500;

    private final ViewerOptions options;
    private final SnapshotListener feed;
    private final Consumer<String> log;
    private final CountDownLatch stopped = new CountDownLatch(1);
    private volatile ViewerClient client;

    /**
     * @param options where to attach
     * @param feed    gets every attempt's run (the window's live feed); told of each run's end
     * @param log     gets what to log, once per change
     */
    public PanelView(ViewerOptions options, SnapshotListener feed, Consumer<String> log) {
        this.options = options;
        this.feed = feed;
        this.log = log;
    }

    /** Attaches, and again after each end or failure, until {@link #stop()}; on the caller's thread. */
    public void run() {
        Reachability reach = new Reachability(options.peer(), FIRST_RETRY_MS);
        while (stopped.getCount() > 0) {
            ViewerClient c = new ViewerClient(options, List.of(feed));
            client = c;
            if (stopped.getCount() == 0) {
                return;
            }
            try {
                ViewerSummary s = c.run();
                if (stopped.getCount() == 0) {
                    return;
                }
                say(reach.failed(Reachability.Failure.ENDED, s.endReason()));
            } catch (ViewerException e) {
                say(reach.failed(kind(e.getMessage()), e.getMessage()));
            }
            try {
                stopped.await(reach.nextDelayMs(), TimeUnit.MILLISECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    /** @return how an attempt failed, from the viewer's message */
    static Reachability.Failure kind(String message) {
        String m = message == null ? "" : message;
        if (m.contains("cannot connect") || m.contains("dropped the connection")
                || m.contains("closed the connection before")) {
            return Reachability.Failure.UNREACHABLE;
        }
        // the viewer client has already tried again a secret that changed since: a refusal here stands
        if (m.contains("refused:") && m.contains(RunSecret.REFUSED_WRONG)) {
            return Reachability.Failure.SECRET_REFUSED;
        }
        if (m.contains("refused:") && m.contains(RunSecret.REFUSED_NONE)) {
            return Reachability.Failure.NO_SECRET;
        }
        return Reachability.Failure.OTHER;
    }

    private void say(String line) {
        if (line != null) {
            log.accept(line);
        }
    }

    /** Detaches and ends {@link #run()}. */
    public void stop() {
        stopped.countDown();
        ViewerClient c = client;
        if (c != null) {
            c.stop();
        }
    }
}
