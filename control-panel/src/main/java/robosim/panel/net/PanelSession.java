package robosim.panel.net;

import java.io.IOException;
import java.net.SocketException;
import java.util.Objects;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Supplier;
import java.util.logging.Logger;
import robosim.panel.model.Reachability;
import robosim.panel.model.Request;
import robosim.protocol.Bye;
import robosim.protocol.CommsUpdate;
import robosim.protocol.ControlReply;
import robosim.protocol.LogLine;
import robosim.protocol.RunSecret;
import robosim.protocol.RunStatus;

/**
 * The panel's two control connections to one Environment, each on a thread of its own so that no
 * caller (the window's event thread above all) ever waits on the network: one carries the user's
 * requests in the order given (a {@code step N} may take long to answer), the other asks for the
 * run's status every {@code periodMs}. Whoever calls {@link #close()} ends both.
 *
 * <p>The run secret is looked up again for every connection opened (see {@link RunSecret#find}), so
 * that a panel attached before its Environment has started, or written its secret, picks it up once
 * it is there; {@link Reachability} says how the status requests fare and when to ask again.
 */
public final class PanelSession implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(PanelSession.class.getName());
    /** The longest wait for an answer: a {@code step N} answers once its steps are run. */
    static final int ANSWER_TIMEOUT_MS = 120_000;
    /** The longest wait for a status. */
    static final int STATUS_TIMEOUT_MS = 10_000;

    private final String host;
    private final int port;
    private final Supplier<String> secrets;
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
    private String statusSecret;
    private volatile boolean closed;
    private volatile Consumer<String> logLines;

    /**
     * @param host  the Environment's host
     * @param port  its viewer port
     * @param token the run secret, or null to find it as every client does, again for each
     *              connection ({@link RunSecret#find})
     */
    public PanelSession(String host, int port, String token) {
        this(host, port, token != null ? (Supplier<String>) () -> token : () -> RunSecret.find(null, host, port));
    }

    private PanelSession(String host, int port, Supplier<String> secrets) {
        this.host = host;
        this.port = port;
        this.secrets = secrets;
    }

    /**
     * A session that asks for the secret to present again for each connection.
     *
     * @param host    the Environment's host
     * @param port    its viewer port
     * @param secrets gives the secret, or null for none; it may throw {@link IllegalArgumentException}
     *                saying why a secret found is unusable
     * @return the session
     */
    public static PanelSession withSecrets(String host, int port, Supplier<String> secrets) {
        return new PanelSession(host, port, secrets);
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
                    requestClient = ControlClient.open(host, port, "control-panel", secrets, ANSWER_TIMEOUT_MS);
                }
                ControlReply reply = requestClient.ask(r.op(), r.args().toArray(String[]::new));
                requestUsedNanos = System.nanoTime();
                return reply;
            } catch (IOException | IllegalArgumentException e) {
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
            try (ControlClient c = ControlClient.open(host, port, "control-panel-comms", secrets, STATUS_TIMEOUT_MS)) {
                c.send(change);
                return c.answer(CommsUpdate.class, u -> true);
            } catch (IOException | IllegalArgumentException e) {
                throw new CompletionException(new IOException("comms: " + e.getMessage(), e));
            }
        }, requests);
    }

    /**
     * Asks for the status now and then every {@code periodMs}, on the status thread, until closed.
     * A failed ask is retried on a fresh connection, with the secret looked up again, after the wait
     * {@link Reachability} gives (longer while the Environment does not answer), so that a panel
     * attached first, or outliving an Environment restarted on the same port, attaches without flooding
     * the log: the log gets one line per change (waiting, gone, stopped, refused, answering again),
     * the run's line says where things stand after every failed ask.
     *
     * @param periodMs how often, ms, while statuses come
     * @param status   gets each status
     * @param line     gets the run's line after each failed ask (why no status comes, and when it is tried again)
     * @param log      gets what to log, once per change
     */
    public void poll(long periodMs, Consumer<RunStatus> status, Consumer<String> line, Consumer<String> log) {
        Reachability reach = new Reachability(peer(), periodMs);
        schedule(() -> pollOnce(reach, status, line, log), 0);
    }

    private void pollOnce(Reachability reach, Consumer<RunStatus> status, Consumer<String> line, Consumer<String> log) {
        if (closed) {
            return;
        }
        try {
            if (statusClient == null) {
                statusSecret = null;
                // looked up once connected: an Environment writes its secret before it listens
                statusClient = ControlClient.open(host, port, "control-panel-status", () -> {
                    statusSecret = secrets.get();
                    return statusSecret;
                }, STATUS_TIMEOUT_MS);
                follow(statusClient, log);
            }
            RunStatus st = statusClient.status();
            String again = reach.reached();
            if (again != null) {
                log.accept(again);
            }
            status.accept(st);
        } catch (IOException | RuntimeException e) {
            closeQuietly(statusClient);
            statusClient = null;
            if (!closed) {
                String say = reach.failed(classify(e, statusSecret), reason(e));
                if (say != null) {
                    log.accept(say);
                }
                line.accept(reach.line());
            }
        }
        schedule(() -> pollOnce(reach, status, line, log), reach.nextDelayMs());
    }

    private void schedule(Runnable task, long delayMs) {
        if (closed) {
            return;
        }
        try {
            polls.schedule(task, delayMs, TimeUnit.MILLISECONDS);
        } catch (RejectedExecutionException e) {
            // closed meanwhile: nothing more to ask
        }
    }

    /**
     * @param e         why a status did not come
     * @param presented the secret that connection presented
     * @return the kind of failure, with the secret found now compared with the one presented
     */
    Reachability.Failure classify(Exception e, String presented) {
        String bye = e instanceof ControlClient.NoAnswerException n ? n.byeReason() : null;
        if (bye != null && bye.startsWith(Bye.DONE)) {
            return Reachability.Failure.ENDED;
        }
        String now;
        try {
            now = secrets.get();
        } catch (IllegalArgumentException unusable) {
            return Reachability.Failure.OTHER;
        }
        if (!Objects.equals(now, presented)) {
            return Reachability.Failure.SECRET_CHANGED;
        }
        if (bye != null && bye.startsWith(Bye.REFUSED)) {
            if (!bye.contains("run secret")) {
                return Reachability.Failure.OTHER;
            }
            return now == null ? Reachability.Failure.NO_SECRET : Reachability.Failure.SECRET_REFUSED;
        }
        if (e instanceof SocketException || e instanceof ControlClient.NoAnswerException) {
            return Reachability.Failure.UNREACHABLE;
        }
        return Reachability.Failure.OTHER;
    }

    /** @return why, in the Environment's words where it gave them */
    private static String reason(Exception e) {
        String bye = e instanceof ControlClient.NoAnswerException n ? n.byeReason() : null;
        if (bye != null) {
            return bye.startsWith(Bye.DONE) ? bye.substring(Bye.DONE.length())
                    : bye.startsWith(Bye.REFUSED) ? bye.substring(Bye.REFUSED.length()) : bye;
        }
        return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
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

    private void follow(ControlClient c, Consumer<String> log) throws IOException {
        Consumer<String> to = logLines;
        if (to == null) {
            return;
        }
        c.onLogLine(l -> to.accept(format(l)));
        ControlReply r = c.ask("log");
        if (!r.ok()) {
            log.accept("the Environment does not send its log: " + r.text());
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
