package robosim.env.net;

/**
 * The caps that keep any client, or many of them, from exhausting the Environment. Every cap has a
 * default ({@link #defaults()}) and an {@code env} option; docs/SECURITY.md says why each default is
 * what it is.
 *
 * @param maxPending      connections that have not yet said hello, on both ports together; at the cap
 *                        the oldest that has been silent a second is closed to make room, and
 *                        while all are younger new connections wait in the listen backlog
 * @param maxRobots       robots in one run; a world that names more is refused
 * @param maxViewers      viewers attached at once
 * @param maxControls     control clients attached at once
 * @param helloDeadlineMs how long a new connection has to say hello before it is closed
 * @param idleTimeoutMs   how long a viewer or control client may take nothing of what is sent to it
 *                        (and a control client may send nothing) before it is closed
 * @param viewerBudget    bytes all viewers' queues may hold together; past it the viewer furthest
 *                        behind is dropped, named, until they fit (one viewer may hold it all)
 */
public record Limits(int maxPending, int maxRobots, int maxViewers, int maxControls, long helloDeadlineMs,
                     long idleTimeoutMs, long viewerBudget) {
    /** The default {@link #maxPending}. */
    public static final int MAX_PENDING = 64;
    /** The default {@link #maxRobots}: the most the benchmark runs. */
    public static final int MAX_ROBOTS = 5000;
    /** The default {@link #maxViewers}. */
    public static final int MAX_VIEWERS = 32;
    /** The default {@link #maxControls}. */
    public static final int MAX_CONTROLS = 4;
    /** The default {@link #helloDeadlineMs}. */
    public static final long HELLO_DEADLINE_MS = 10_000;
    /** The default {@link #idleTimeoutMs}. */
    public static final long IDLE_TIMEOUT_MS = 120_000;
    /** The default {@link #viewerBudget}: 256 MiB. */
    public static final long VIEWER_BUDGET = 256L << 20;

    /** Checks every value; a bad one is named with the rule it breaks. */
    public Limits {
        ServerOptions.requireAtLeast("maxPending", maxPending, 1);
        ServerOptions.requireAtLeast("maxRobots", maxRobots, 1);
        ServerOptions.requireAtLeast("maxViewers", maxViewers, 0);
        ServerOptions.requireAtLeast("maxControls", maxControls, 0);
        ServerOptions.requireAtLeast("helloDeadlineMs", helloDeadlineMs, 1);
        ServerOptions.requireAtLeast("idleTimeoutMs", idleTimeoutMs, 1);
        ServerOptions.requireAtLeast("viewerBudget", viewerBudget, 1 << 16);
    }

    /** @return every cap at its default */
    public static Limits defaults() {
        return new Limits(MAX_PENDING, MAX_ROBOTS, MAX_VIEWERS, MAX_CONTROLS, HELLO_DEADLINE_MS, IDLE_TIMEOUT_MS,
                VIEWER_BUDGET);
    }

    /** @param n connections without a hello @return a copy with it */
    public Limits withMaxPending(int n) {
        return new Limits(n, maxRobots, maxViewers, maxControls, helloDeadlineMs, idleTimeoutMs, viewerBudget);
    }

    /** @param n viewers @return a copy with it */
    public Limits withMaxViewers(int n) {
        return new Limits(maxPending, maxRobots, n, maxControls, helloDeadlineMs, idleTimeoutMs, viewerBudget);
    }

    /** @param ms the hello deadline @return a copy with it */
    public Limits withHelloDeadlineMs(long ms) {
        return new Limits(maxPending, maxRobots, maxViewers, maxControls, ms, idleTimeoutMs, viewerBudget);
    }

    /** @param ms the idle timeout @return a copy with it */
    public Limits withIdleTimeoutMs(long ms) {
        return new Limits(maxPending, maxRobots, maxViewers, maxControls, helloDeadlineMs, ms, viewerBudget);
    }

    /** @param bytes the viewers' budget @return a copy with it */
    public Limits withViewerBudget(long bytes) {
        return new Limits(maxPending, maxRobots, maxViewers, maxControls, helloDeadlineMs, idleTimeoutMs, bytes);
    }
}
