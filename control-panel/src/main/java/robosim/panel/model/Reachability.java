package robosim.panel.model;

import java.util.Locale;

/**
 * Whether the panel reaches its Environment, from the outcome of each status request: what the
 * run's line says while no status comes, what the log says (once per change, never once per
 * attempt), and how long to wait before asking again. Pure: the caller does the asking.
 *
 * <p>The rule every client of the run follows: a refusal that can clear (nothing listens yet, the
 * Environment has not written its secret yet, or the secret found now differs from the one
 * presented) is retried quietly, sooner at first and then every {@value #MAX_RETRY_MS} ms; a final
 * refusal (the same secret refused again) is said once and then retried only every
 * {@value #REFUSED_RETRY_MS} ms, as the run's line says. An Environment that was reached and no longer
 * answers is "gone"; one that said its run is done has "stopped", and stays so until it answers again.
 */
public final class Reachability {
    /** The longest wait between two tries while the Environment does not answer, ms. */
    public static final long MAX_RETRY_MS = 5_000;
    /** The wait between two tries after a final refusal, ms. */
    public static final long REFUSED_RETRY_MS = 30_000;

    /** How a status request failed. */
    public enum Failure {
        /** Nothing answers at the port, or the connection closed before an answer. */
        UNREACHABLE,
        /** The Environment wants a secret and none is found yet (it may not have written it yet). */
        NO_SECRET,
        /** The secret presented was refused, and the one found now differs: try it at once. */
        SECRET_CHANGED,
        /** The secret presented was refused, and it is still the one found: a final refusal. */
        SECRET_REFUSED,
        /** The Environment said its run is done. */
        ENDED,
        /** Anything else: a timeout, a broken frame, another refusal. */
        OTHER
    }

    private enum State { NEW, STARTING, ATTACHED, WAITING_SECRET, GONE, STOPPED, REFUSED, FAILING }

    private final String peer;
    private final long periodMs;
    private State state = State.NEW;
    private boolean everAttached;
    private int misses;
    private String detail = "";

    /**
     * @param peer     the Environment's host:port, for the messages
     * @param periodMs how often a status is asked for while it comes, ms, at least 1
     * @throws IllegalArgumentException if the period is below 1 ms
     */
    public Reachability(String peer, long periodMs) {
        if (periodMs < 1) {
            throw new IllegalArgumentException(periodMs + " was supplied for periodMs: it must be at least 1 ms");
        }
        this.peer = peer;
        this.periodMs = periodMs;
    }

    /**
     * A status came.
     *
     * @return what to log: that the Environment answers again after a gap, or null
     */
    public String reached() {
        State before = state;
        state = State.ATTACHED;
        misses = 0;
        boolean again = everAttached && before != State.ATTACHED;
        everAttached = true;
        return again ? "the Environment at " + peer + " answers again" : null;
    }

    /**
     * A status did not come.
     *
     * @param kind   how it failed
     * @param reason the Environment's or the system's words, for the messages
     * @return what to log, once per change of state or reason; null to stay quiet
     */
    public String failed(Failure kind, String reason) {
        String why = reason == null ? "" : reason;
        if (kind == Failure.SECRET_CHANGED) {
            // a newer secret is there to present: no news, try again at once
            misses = 0;
            return null;
        }
        if (kind == Failure.UNREACHABLE && state == State.STOPPED) {
            // an Environment whose run is done exits: its silence is expected
            misses++;
            return null;
        }
        State next = switch (kind) {
            case UNREACHABLE -> everAttached ? State.GONE : State.STARTING;
            case NO_SECRET -> State.WAITING_SECRET;
            case SECRET_REFUSED -> State.REFUSED;
            case ENDED -> State.STOPPED;
            default -> State.FAILING;
        };
        boolean news = next != state || (next == State.FAILING || next == State.REFUSED) && !why.equals(detail);
        misses = next == state ? misses + 1 : 1;
        state = next;
        detail = why;
        if (!news) {
            return null;
        }
        return switch (next) {
            case STARTING -> "waiting for the Environment at " + peer + " to start (" + why + ")";
            case WAITING_SECRET -> "waiting for the run secret of " + peer + ": " + why;
            case GONE -> "the Environment at " + peer + " is gone (" + why + "); trying again every "
                    + seconds(MAX_RETRY_MS);
            case STOPPED -> "the run at " + peer + " has stopped: " + why;
            case REFUSED -> "the Environment at " + peer + " refuses this panel: " + why + "; trying again every "
                    + seconds(REFUSED_RETRY_MS) + " (give the run's secret with --secret-file, or attach again)";
            default -> "no status from " + peer + ": " + why;
        };
    }

    /** @return how long to wait before the next status request, ms */
    public long nextDelayMs() {
        if (state == State.ATTACHED || misses == 0) {
            return periodMs;
        }
        if (state == State.REFUSED) {
            return REFUSED_RETRY_MS;
        }
        long backoff = periodMs << Math.min(misses - 1, 16);
        return Math.min(MAX_RETRY_MS, Math.max(periodMs, backoff));
    }

    /** @return whether the last status request was answered */
    public boolean attached() {
        return state == State.ATTACHED;
    }

    /** @return the run's line while no status comes; null while statuses come */
    public String line() {
        String retry = " (trying again every " + seconds(nextDelayMs()) + ")";
        return switch (state) {
            case ATTACHED -> null;
            case NEW -> "attaching to the Environment at " + peer;
            case STARTING -> "waiting for the Environment at " + peer + " to start" + retry;
            case WAITING_SECRET -> "waiting for the run secret of " + peer + retry;
            case GONE -> "Environment gone: " + peer + " does not answer" + retry;
            case STOPPED -> "stopped: " + detail;
            case REFUSED -> "refused: " + detail + retry;
            default -> "no status: " + detail + retry;
        };
    }

    private static String seconds(long ms) {
        return ms % 1000 == 0 ? ms / 1000 + " s" : String.format(Locale.ROOT, "%.1f s", ms / 1000.0);
    }
}
