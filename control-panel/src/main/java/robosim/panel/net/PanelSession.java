package robosim.panel.net;

import java.io.IOException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.logging.Logger;
import robosim.panel.model.Request;
import robosim.protocol.CommsUpdate;
import robosim.protocol.ControlReply;
import robosim.protocol.LogLine;
import robosim.protocol.RunStatus;

/**
 * The panel's two control connections to one Environment, each on a thread of its own so that no
 * caller (the window's event thread above all) ever waits on the network: one carries the user's
 * requests in the order given (a {@code step N} may take long to answer), the other asks for the
 * run's status every {@code periodMs}. Whoever calls {@link #close()} ends both.
 */
public final class PanelSession implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(PanelSession.class.getName());
    /** The longest wait for an answer: a {@code step N} answers once its steps are run. */
    static final int ANSWER_TIMEOUT_MS = 120_000;
    /** The longest wait for a status. */
    static final int STATUS_TIMEOUT_MS = 10_000;

    private final String host;
    private final int port;
    private final String token;
    private final ExecutorService requests = Executors.newSingleThreadExecutor(daemon("panel-requests"));
    private final ScheduledExecutorService polls = Executors.newSingleThreadScheduledExecutor(daemon("panel-status"));
    /**
     * A request connection quiet for longer than this is replaced before use: the Environment closes
     * a control client that sends nothing for its idle timeout (two minutes by default), and a
     * request sent into a connection it is closing would be lost.
     */
    static final long REOPEN_AFTER_MS = 60_000;

    private volatile ControlClient requestClient;
    private long requestUsedNanos;
    private volatile ControlClient statusClient;
    private volatile boolean closed;
    private volatile Consumer<String> logLines;

    /**
     * @param host  the Environment's host
     * @param port  its viewer port
     * @param token the run secret, or null
     */
    public PanelSession(String host, int port, String token) {
        this.host = host;
        this.port = port;
        this.token = token;
    }

    /** @return where the session's Environment is, host:port */
    public String peer() {
        return host + ":" + port;
    }

    /**
     * Sends a request on the requests' thread.
     *
     * @param r the request
     * @return the Environment's reply; completes exceptionally, saying why, when none comes
     */
    public CompletableFuture<ControlReply> send(Request r) {
        return CompletableFuture.supplyAsync(() -> {
            try {
                long now = System.nanoTime();
                if (requestClient != null && now - requestUsedNanos > TimeUnit.MILLISECONDS.toNanos(REOPEN_AFTER_MS)) {
                    closeQuietly(requestClient);
                    requestClient = null;
                }
                if (requestClient == null) {
                    requestClient = ControlClient.open(host, port, "control-panel", token, ANSWER_TIMEOUT_MS);
                }
                ControlReply reply = requestClient.ask(r.op(), r.args().toArray(String[]::new));
                requestUsedNanos = System.nanoTime();
                return reply;
            } catch (IOException e) {
                closeQuietly(requestClient);
                requestClient = null;
                throw new CompletionException(new IOException(r + ": " + e.getMessage(), e));
            }
        }, requests);
    }

    /**
     * Changes the comms settings, on the requests' thread, over a connection of its own (the
     * Environment closes a connection whose settings break a rule).
     *
     * @param change the settings to change; null fields are kept
     * @return the settings now in force; completes exceptionally, saying why, when refused
     */
    public CompletableFuture<CommsUpdate> comms(CommsUpdate change) {
        return CompletableFuture.supplyAsync(() -> {
            try (ControlClient c = ControlClient.open(host, port, "control-panel-comms", token, STATUS_TIMEOUT_MS)) {
                c.send(change);
                return c.answer(CommsUpdate.class, u -> true);
            } catch (IOException e) {
                throw new CompletionException(new IOException("comms: " + e.getMessage(), e));
            }
        }, requests);
    }

    /**
     * Asks for the status now and then every {@code periodMs}, on the status thread, until closed.
     * A failed ask is reported and retried on a fresh connection at the next period, so that a
     * panel outlives an Environment that is restarted on the same port.
     *
     * @param periodMs how often, ms
     * @param status   gets each status
     * @param failure  gets why a status did not come
     */
    public void poll(long periodMs, Consumer<RunStatus> status, Consumer<String> failure) {
        polls.scheduleWithFixedDelay(() -> {
            if (closed) {
                return;
            }
            try {
                if (statusClient == null) {
                    statusClient = ControlClient.open(host, port, "control-panel-status", token, STATUS_TIMEOUT_MS);
                    follow(statusClient, failure);
                }
                status.accept(statusClient.status());
            } catch (IOException | RuntimeException e) {
                closeQuietly(statusClient);
                statusClient = null;
                if (!closed) {
                    failure.accept("no status from " + peer() + ": " + e.getMessage());
                }
            }
        }, 0, periodMs, TimeUnit.MILLISECONDS);
    }

    /**
     * Has the Environment's log lines (INFO and above) come to {@code lines}, formatted as
     * {@code [step 12] WARNING: text}, read along with the statuses; call it before {@link #poll}.
     * The status connection asks for them again whenever it is opened anew.
     *
     * @param lines gets each line, on the status thread
     */
    public void followLog(Consumer<String> lines) {
        this.logLines = lines;
    }

    private void follow(ControlClient c, Consumer<String> failure) throws IOException {
        Consumer<String> to = logLines;
        if (to == null) {
            return;
        }
        c.onLogLine(l -> to.accept(format(l)));
        ControlReply r = c.ask("log");
        if (!r.ok()) {
            failure.accept("the Environment does not send its log: " + r.text());
        }
    }

    /** @return a log line as the panel's log pane shows it */
    static String format(LogLine l) {
        return "[step " + l.step() + "] " + (l.level().equals("INFO") ? "" : l.level() + ": ") + l.text();
    }

    /** Stops both threads and closes both connections; a request under way ends with an error. */
    @Override
    public void close() {
        closed = true;
        polls.shutdownNow();
        requests.shutdownNow();
        // closing the sockets from here wakes a thread blocked reading an answer
        closeQuietly(requestClient);
        closeQuietly(statusClient);
        try {
            requests.awaitTermination(5, TimeUnit.SECONDS);
            polls.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static void closeQuietly(ControlClient c) {
        if (c != null) {
            try {
                c.close();
            } catch (IOException e) {
                LOG.fine(() -> "closing a control connection: " + e.getMessage());
            }
        }
    }

    private static ThreadFactory daemon(String name) {
        return r -> {
            Thread t = new Thread(r, name);
            t.setDaemon(true);
            return t;
        };
    }
}
