package robosim.env.net;

import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import robosim.env.core.Simulation;

/**
 * The step loop's side of {@link RunProgress}: when the listener is next due, since when the run
 * and the current wait have lasted, and the {@link RunProgress.Status} it is given. With no
 * listener nothing is ever due, so the step loop need not read the clock for it.
 */
final class ProgressReports {
    private static final Logger LOG = Logger.getLogger(EnvironmentServer.class.getName());

    private final SessionRules rules;
    private final ServerOptions options;
    private RunProgress listener;
    private long intervalNanos;
    /** When the listener is next due, {@link System#nanoTime()}; far away when no one follows. */
    private long nextNanos = Long.MAX_VALUE;
    private long waitStartedNanos;
    /** Whether a wait for robots counts against the connect timeout. */
    private boolean connectTimed = true;
    private long runStartedNanos;
    /** How long the step held now may wait, ms: the step timeout, or the first steps' when a robot has it. */
    private long stepLimitMs;

    ProgressReports(SessionRules rules, ServerOptions options) {
        this.rules = rules;
        this.options = options;
    }

    private Simulation sim() {
        return rules.sim();
    }

    /** @see EnvironmentServer#setProgress */
    void follow(RunProgress follower, long intervalMs) {
        if (intervalMs < 1) {
            throw new IllegalArgumentException(intervalMs + " was supplied for intervalMs: it must be at least 1");
        }
        listener = follower;
        intervalNanos = TimeUnit.MILLISECONDS.toNanos(intervalMs);
        nextNanos = follower == null ? Long.MAX_VALUE : System.nanoTime() + intervalNanos;
    }

    /** @return whether someone follows the run */
    boolean following() {
        return listener != null;
    }

    /** @param now when the wait that a report of {@code CONNECTING} or {@code STEP_HELD} counts began */
    void waitingSince(long now) {
        waitStartedNanos = now;
        connectTimed = true;
        stepLimitMs = options.stepTimeoutMs();
    }

    /** @param ms how long the step held now may wait in all: longer while a robot in its first steps is waited for */
    void stepLimit(long ms) {
        stepLimitMs = ms;
    }

    /**
     * @param now when a wait for robots began that has no time limit (after a restart or load: the
     *            user drives the Environment then)
     */
    void waitingUntimedSince(long now) {
        waitStartedNanos = now;
        connectTimed = false;
    }

    /** @param now when the first step began */
    void runningSince(long now) {
        runStartedNanos = now;
    }

    /**
     * @param now   {@link System#nanoTime()}
     * @param other when the caller would wake anyway
     * @return the sooner of {@code other} and the next report, for a select that waits
     */
    long wakeBy(long now, long other) {
        return listener != null && nextNanos - now > 0 ? Math.min(other, nextNanos) : other;
    }

    /** Tells the listener where the run is, if a report is due. */
    void reportIfDue(RunProgress.Phase phase, long now) {
        if (listener == null || now - nextNanos < 0) {
            return;
        }
        nextNanos = now + intervalNanos;
        List<String> waitingFor = switch (phase) {
            case CONNECTING -> rules.missing();
            case STEP_HELD -> List.copyOf(rules.waitingFor());
            case RUNNING -> List.of();
        };
        long limitMs = switch (phase) {
            case CONNECTING -> connectTimed ? options.connectTimeoutMs() : 0;
            case STEP_HELD -> stepLimitMs;
            case RUNNING -> 0;
        };
        long runNanos = phase == RunProgress.Phase.CONNECTING ? 0 : now - runStartedNanos;
        long waitedNanos = phase == RunProgress.Phase.RUNNING ? 0 : now - waitStartedNanos;
        try {
            listener.progress(new RunProgress.Status(phase, sim().stepCount(), sim().timeMs(), sim().world().stepMs(),
                    options.maxSteps(), sim().robotNames().size(), rules.connectedRobots().size(), waitingFor,
                    rules.viewerCount(), options.waitViewers(), runNanos, waitedNanos,
                    TimeUnit.MILLISECONDS.toNanos(limitMs),
                    phase == RunProgress.Phase.CONNECTING ? rules.refusals() : Map.of()));
        } catch (RuntimeException e) {
            // progress is a courtesy: a listener that fails is logged and dropped, the run goes on
            LOG.warning(() -> "the progress listener failed and is dropped: " + e);
            listener = null;
            nextNanos = Long.MAX_VALUE;
        }
    }
}
