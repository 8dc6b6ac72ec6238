package robosim.pioneer.server;

import robosim.hw.HardwareOptions;

/**
 * How the Pioneer ports listen and behave.
 *
 * @param bind         the address they listen on (loopback unless told otherwise: an ARIA client
 *                     cannot present the run secret)
 * @param firstPort    the first robot's port; the others follow in the world's order
 * @param allowSimExit whether SIM_EXIT may end the run
 * @param watchdogMs   a client silent this long stops its robot, as a Pioneer's watchdog does
 * @param realTime     whether steps are paced at the world's step length while a client is attached
 * @param hardware     the bridge robots' timeouts towards the Environment
 * @param handshakeMs  a client that has not finished the handshake in this long is closed, so that
 *                     the port is free again
 * @param silentMs     a client silent this long gives its port to the next client that connects
 */
public record PioneerPortOptions(String bind, int firstPort, boolean allowSimExit, long watchdogMs, boolean realTime,
                                 HardwareOptions hardware, long handshakeMs, long silentMs) {
    /** How long a client may take over the SYNC handshake, ms. */
    public static final long DEFAULT_HANDSHAKE_MS = 10_000;
    /**
     * How long a client may be silent before it gives its port to the next client, ms: longer than a
     * running ARIA program ever is (it sends a PULSE every 500 ms).
     */
    public static final long DEFAULT_SILENT_MS = 15_000;

    /** A Pioneer's watchdog time, as MobileSim reports it in the CONFIG reply, ms. */
    public static final long DEFAULT_WATCHDOG_MS = 2000;

    /**
     * @throws IllegalArgumentException if the first port leaves no room or the watchdog is not positive
     */
    public PioneerPortOptions {
        if (firstPort < 0 || firstPort > 65535) {
            throw new IllegalArgumentException(firstPort + " was supplied for the first Pioneer port: a port is 0 to 65535"
                    + " (0: any free port for each robot)");
        }
        if (watchdogMs <= 0) {
            throw new IllegalArgumentException(watchdogMs + " was supplied for the watchdog: it must be above 0 ms");
        }
        if (handshakeMs <= 0 || silentMs <= 0) {
            throw new IllegalArgumentException(handshakeMs + " ms and " + silentMs + " ms were supplied for the"
                    + " handshake and the silence a client is allowed: each must be above 0 ms");
        }
    }

    /**
     * Options with the default patience with clients: {@value #DEFAULT_HANDSHAKE_MS} ms for the
     * handshake, {@value #DEFAULT_SILENT_MS} ms of silence.
     *
     * @param bind         the address they listen on
     * @param firstPort    the first robot's port
     * @param allowSimExit whether SIM_EXIT may end the run
     * @param watchdogMs   a client silent this long stops its robot
     * @param realTime     whether steps are paced at the world's step length while a client is attached
     * @param hardware     the bridge robots' timeouts towards the Environment
     */
    public PioneerPortOptions(String bind, int firstPort, boolean allowSimExit, long watchdogMs, boolean realTime,
                              HardwareOptions hardware) {
        this(bind, firstPort, allowSimExit, watchdogMs, realTime, hardware, DEFAULT_HANDSHAKE_MS, DEFAULT_SILENT_MS);
    }

    /**
     * @param handshake how long a client may take over the handshake, ms
     * @param silence   how long a client may be silent before it gives way to the next, ms
     * @return these options with that patience
     */
    public PioneerPortOptions withPatience(long handshake, long silence) {
        return new PioneerPortOptions(bind, firstPort, allowSimExit, watchdogMs, realTime, hardware, handshake, silence);
    }
}
