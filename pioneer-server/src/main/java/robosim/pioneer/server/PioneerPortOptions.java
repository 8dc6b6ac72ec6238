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
 */
public record PioneerPortOptions(String bind, int firstPort, boolean allowSimExit, long watchdogMs, boolean realTime,
                                 HardwareOptions hardware) {
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
    }
}
