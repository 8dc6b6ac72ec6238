package robosim.env.net;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Follows an {@link EnvironmentServer}'s run for a launcher that shows its progress: the server
 * calls it on its step loop's thread, at most once per interval given to
 * {@link EnvironmentServer#setProgress}, while it waits for the world's robots, while it runs, and
 * while a step waits for late robots. The step loop reads the clock once a step for it, and not at
 * all when no one follows the run; a listener must return quickly (print a line, no more).
 */
@FunctionalInterface
public interface RunProgress {
    /**
     * Where the run is.
     *
     * @param status what the server is doing and waiting for
     */
    void progress(Status status);

    /** What the Environment is doing. */
    enum Phase {
        /** Waiting for the world's robots (and the viewers asked for) to connect, before the first step. */
        CONNECTING,
        /** Running steps. */
        RUNNING,
        /** A step waits for the requests of robots that have not sent them yet. */
        STEP_HELD
    }

    /**
     * What the Environment is doing at one moment.
     *
     * @param phase           what it is doing
     * @param step            the last step run; 0 before the first
     * @param timeMs          simulated time after that step, ms
     * @param stepMs          the world's step length, simulated ms
     * @param maxSteps        the step limit; 0 when the run has none
     * @param robots          the robots the world names
     * @param connected       the robots connected now
     * @param waitingFor      the robots waited for: while {@link Phase#CONNECTING} those not connected yet,
     *                        while {@link Phase#STEP_HELD} those whose requests have not come; else empty
     * @param viewers         the viewers connected now
     * @param viewersAwaited  the viewers the first step waits for (0: none)
     * @param runNanos        wall time since the first step opened (0 while connecting), ns
     * @param waitedNanos     while connecting: since the server began to wait for robots; while a step
     *                        is held: since the step opened; else 0; ns
     * @param waitLimitNanos  how long that wait may last (the connect or the step timeout); 0 while running,
     *                        and while connecting after a restart or load, which has no time limit
     * @param refused         while {@link Phase#CONNECTING}: the robots (or shared links) refused since the wait
     *                        began and not connected since, with the first clause of why, oldest first; else empty
     */
    record Status(Phase phase, long step, long timeMs, int stepMs, long maxSteps, int robots, int connected,
                  List<String> waitingFor, int viewers, int viewersAwaited, long runNanos, long waitedNanos,
                  long waitLimitNanos, Map<String, String> refused) {
        /** Copies the list of robots waited for and the refusals, keeping their order. */
        public Status {
            waitingFor = List.copyOf(waitingFor);
            refused = Collections.unmodifiableMap(new LinkedHashMap<>(refused));
        }

        /** A status with no refusals. */
        public Status(Phase phase, long step, long timeMs, int stepMs, long maxSteps, int robots, int connected,
                      List<String> waitingFor, int viewers, int viewersAwaited, long runNanos, long waitedNanos,
                      long waitLimitNanos) {
            this(phase, step, timeMs, stepMs, maxSteps, robots, connected, waitingFor, viewers, viewersAwaited, runNanos,
                    waitedNanos, waitLimitNanos, Map.of());
        }
    }
}
