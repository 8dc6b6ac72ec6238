package robosim.env.net;

import robosim.protocol.FrameReader;

/**
 * How an {@link EnvironmentServer} runs.
 *
 * @param bindAddress      address to listen on, normally 127.0.0.1
 * @param robotPort        port for robots, 0 for any free one
 * @param viewerPort       port for viewers, 0 for any free one
 * @param maxSteps         stop after this many steps; 0 runs until every robot has left
 * @param realtime         pace steps at the world's step length instead of as fast as possible
 * @param stepTimeoutMs    how long to wait for a robot's requests before disconnecting it
 * @param connectTimeoutMs how long to wait for the world's robots (and viewers) to connect
 * @param waitViewers      viewers to wait for before the first step
 * @param maxFrame         largest frame accepted, bytes
 * @param threads          threads that read the robots' sensors each step, at least 1 (1: all on the
 *                         step loop's thread); the run is the same with any number
 * @param limits           the caps on connections and queues
 * @param access           who may use the ports: the run secret, whether viewers need it
 * @param firstStepsTimeoutMs how long to wait for a robot's requests in each of its first
 *                         {@link #FIRST_STEPS} steps, if longer than {@code stepTimeoutMs}: a robot's
 *                         program loads its classes and warms up then, which on a busy machine may
 *                         take many seconds
 */
public record ServerOptions(String bindAddress, int robotPort, int viewerPort, long maxSteps, boolean realtime,
                            long stepTimeoutMs, long connectTimeoutMs, int waitViewers, int maxFrame, int threads,
                            Limits limits, Access access, long firstStepsTimeoutMs) {
    /** The steps of a robot, from the first it takes part in, that wait up to {@link #firstStepsTimeoutMs}. */
    public static final int FIRST_STEPS = 3;
    /** The default of {@link #firstStepsTimeoutMs}, ms. */
    public static final long DEFAULT_FIRST_STEPS_TIMEOUT_MS = 60_000;

    /** Checks every value; a bad one is named with the rule it breaks. */
    public ServerOptions {
        requirePort("robotPort", robotPort);
        requirePort("viewerPort", viewerPort);
        requireAtLeast("maxSteps", maxSteps, 0);
        requireAtLeast("stepTimeoutMs", stepTimeoutMs, 1);
        requireAtLeast("connectTimeoutMs", connectTimeoutMs, 1);
        requireAtLeast("firstStepsTimeoutMs", firstStepsTimeoutMs, 1);
        requireAtLeast("waitViewers", waitViewers, 0);
        requireAtLeast("maxFrame", maxFrame, 64);
        requireAtLeast("threads", threads, 1);
        if (limits == null || access == null) {
            throw new IllegalArgumentException("limits and access must be given (Limits.defaults(), Access.open())");
        }
    }

    /**
     * Options whose robots' first steps wait {@link #DEFAULT_FIRST_STEPS_TIMEOUT_MS} (or the step
     * timeout, if longer).
     *
     * @param bindAddress      address to listen on, normally 127.0.0.1
     * @param robotPort        port for robots, 0 for any free one
     * @param viewerPort       port for viewers, 0 for any free one
     * @param maxSteps         stop after this many steps; 0 runs until every robot has left
     * @param realtime         pace steps at the world's step length instead of as fast as possible
     * @param stepTimeoutMs    how long to wait for a robot's requests before disconnecting it
     * @param connectTimeoutMs how long to wait for the world's robots (and viewers) to connect
     * @param waitViewers      viewers to wait for before the first step
     * @param maxFrame         largest frame accepted, bytes
     * @param threads          threads that read the robots' sensors each step
     * @param limits           the caps on connections and queues
     * @param access           who may use the ports
     */
    public ServerOptions(String bindAddress, int robotPort, int viewerPort, long maxSteps, boolean realtime,
                         long stepTimeoutMs, long connectTimeoutMs, int waitViewers, int maxFrame, int threads,
                         Limits limits, Access access) {
        this(bindAddress, robotPort, viewerPort, maxSteps, realtime, stepTimeoutMs, connectTimeoutMs, waitViewers,
                maxFrame, threads, limits, access, DEFAULT_FIRST_STEPS_TIMEOUT_MS);
    }

    /**
     * @param step a robot's step, counted from 1 at the first step it takes part in
     * @return how long the Environment waits for its requests in that step, ms
     */
    public long stepTimeoutMs(long step) {
        return step <= FIRST_STEPS ? Math.max(stepTimeoutMs, firstStepsTimeoutMs) : stepTimeoutMs;
    }

    /** @param ms the first steps' timeout @return a copy with it */
    public ServerOptions withFirstStepsTimeoutMs(long ms) {
        return new ServerOptions(bindAddress, robotPort, viewerPort, maxSteps, realtime, stepTimeoutMs,
                connectTimeoutMs, waitViewers, maxFrame, threads, limits, access, ms);
    }

    /**
     * Options with as many threads as the machine has processors ({@link #defaultThreads()}), the
     * default {@link Limits} and no run secret ({@link Access#open()}).
     *
     * @param bindAddress      address to listen on, normally 127.0.0.1
     * @param robotPort        port for robots, 0 for any free one
     * @param viewerPort       port for viewers, 0 for any free one
     * @param maxSteps         stop after this many steps; 0 runs until every robot has left
     * @param realtime         pace steps at the world's step length instead of as fast as possible
     * @param stepTimeoutMs    how long to wait for a robot's requests before disconnecting it
     * @param connectTimeoutMs how long to wait for the world's robots (and viewers) to connect
     * @param waitViewers      viewers to wait for before the first step
     * @param maxFrame         largest frame accepted, bytes
     */
    public ServerOptions(String bindAddress, int robotPort, int viewerPort, long maxSteps, boolean realtime,
                         long stepTimeoutMs, long connectTimeoutMs, int waitViewers, int maxFrame) {
        this(bindAddress, robotPort, viewerPort, maxSteps, realtime, stepTimeoutMs, connectTimeoutMs, waitViewers,
                maxFrame, defaultThreads(), Limits.defaults(), Access.open());
    }

    /** @return the threads a server uses unless told otherwise: the processors the JVM may use */
    public static int defaultThreads() {
        return Runtime.getRuntime().availableProcessors();
    }

    /**
     * Defaults for tests and tools: loopback, any free ports, as fast as possible.
     *
     * @return the options
     */
    public static ServerOptions loopback() {
        return new ServerOptions("127.0.0.1", 0, 0, 0, false, 10_000, 60_000, 0, FrameReader.DEFAULT_MAX_FRAME);
    }

    /** @param steps the step limit @return a copy with it */
    public ServerOptions withMaxSteps(long steps) {
        return new ServerOptions(bindAddress, robotPort, viewerPort, steps, realtime, stepTimeoutMs,
                connectTimeoutMs, waitViewers, maxFrame, threads, limits, access, firstStepsTimeoutMs);
    }

    /** @param viewers viewers to wait for @return a copy with it */
    public ServerOptions withWaitViewers(int viewers) {
        return new ServerOptions(bindAddress, robotPort, viewerPort, maxSteps, realtime, stepTimeoutMs,
                connectTimeoutMs, viewers, maxFrame, threads, limits, access, firstStepsTimeoutMs);
    }

    /** @param count threads that read the sensors @return a copy with it */
    public ServerOptions withThreads(int count) {
        return new ServerOptions(bindAddress, robotPort, viewerPort, maxSteps, realtime, stepTimeoutMs,
                connectTimeoutMs, waitViewers, maxFrame, count, limits, access, firstStepsTimeoutMs);
    }

    /** @param caps the caps on connections and queues @return a copy with them */
    public ServerOptions withLimits(Limits caps) {
        return new ServerOptions(bindAddress, robotPort, viewerPort, maxSteps, realtime, stepTimeoutMs,
                connectTimeoutMs, waitViewers, maxFrame, threads, caps, access, firstStepsTimeoutMs);
    }

    /** @param rules who may use the ports @return a copy with them */
    public ServerOptions withAccess(Access rules) {
        return new ServerOptions(bindAddress, robotPort, viewerPort, maxSteps, realtime, stepTimeoutMs,
                connectTimeoutMs, waitViewers, maxFrame, threads, limits, rules, firstStepsTimeoutMs);
    }

    /**
     * The rule for a listening port, shared with command lines so that an error names the flag the
     * user typed.
     *
     * @param name  what the value was supplied for: a parameter or a flag
     * @param value the port
     * @throws IllegalArgumentException naming the value, the name and the rule, if it is not 0 to 65535
     */
    public static void requirePort(String name, int value) {
        if (value < 0 || value > 65535) {
            throw new IllegalArgumentException(value + " was supplied for " + name
                    + ": a port is 0 to 65535, 0 for any free port");
        }
    }

    /**
     * The rule for a count or a time with a lower bound, shared with command lines so that an error
     * names the flag the user typed.
     *
     * @param name  what the value was supplied for: a parameter or a flag
     * @param value the value
     * @param min   the least value allowed
     * @throws IllegalArgumentException naming the value, the name and the rule, if it is below {@code min}
     */
    public static void requireAtLeast(String name, long value, long min) {
        if (value < min) {
            throw new IllegalArgumentException(value + " was supplied for " + name + ": it must be at least " + min);
        }
    }

    /**
     * The rule for a value with an upper bound, shared with command lines so that an error names the
     * flag the user typed.
     *
     * @param name  what the value was supplied for: a parameter or a flag
     * @param value the value
     * @param max   the greatest value allowed
     * @throws IllegalArgumentException naming the value, the name and the rule, if it is above {@code max}
     */
    public static void requireAtMost(String name, long value, long max) {
        if (value > max) {
            throw new IllegalArgumentException(value + " was supplied for " + name + ": it must be at most " + max);
        }
    }
}
