package robosim.hw;

import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Chooses each robot's {@link EnvironmentLink}. By default ({@code auto}) a robot alone in its JVM
 * has a connection of its own, with one frame per robot each way each step, as every robot had
 * before shared links; from the second robot of a JVM connected to the same Environment on, the
 * robots share one connection, each step's states arriving in one frame and their requests leaving
 * in one. Runs are the same either way: the Environment steps each robot as it would over a
 * connection of its own.
 *
 * <p>The system property {@code robosim.link} overrides the choice: {@code own} gives every robot a
 * connection of its own, {@code shared} puts every robot, the first too, on the shared one.
 *
 * <p>The system property {@value #PIONEER_PROPERTY}, set to a Pioneer robot server's
 * {@code host:port}, sends every robot of the JVM there instead, through a {@link PioneerLink}: the
 * same program then drives MobileSim, a real Pioneer behind a serial-to-TCP bridge, or RoboSim's
 * own Pioneer port, whatever Environment host and port it was given.
 */
public final class EnvironmentLinks {
    /** The system property that chooses the links. */
    public static final String PROPERTY = "robosim.link";
    /** The system property that sends the robots to a Pioneer robot server, {@code host:port}. */
    public static final String PIONEER_PROPERTY = "robosim.pioneer";
    /** Robots of this JVM connected or connecting, by the Environment's host and port. */
    private static final Map<String, Integer> ROBOTS = new ConcurrentHashMap<>();

    private EnvironmentLinks() {
    }

    /** How robots reach the Environment. */
    public enum Mode {
        /** The first robot of a JVM alone, the others sharing one connection. */
        AUTO,
        /** A connection for each robot. */
        OWN,
        /** One connection for every robot of the JVM. */
        SHARED;

        /**
         * @return the mode {@value #PROPERTY} names, {@link #AUTO} if unset
         * @throws IllegalArgumentException if it names none
         */
        public static Mode configured() {
            String value = System.getProperty(PROPERTY, "auto");
            try {
                return valueOf(value.trim().toUpperCase(Locale.ROOT));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("'" + value + "' was supplied for the system property " + PROPERTY
                        + ": it is auto, own or shared", e);
            }
        }
    }

    /**
     * A link for one robot, not yet open, as {@link Mode#configured()} chooses.
     *
     * @param host    the Environment's host
     * @param port    its robot port
     * @param options timeouts
     * @return the link
     */
    public static EnvironmentLink to(String host, int port, HardwareOptions options) {
        String pioneer = System.getProperty(PIONEER_PROPERTY);
        if (pioneer != null && !pioneer.isBlank()) {
            return pioneer(pioneer, options);
        }
        return toEnvironment(host, port, options);
    }

    /**
     * A link to the Environment itself, whatever {@value #PIONEER_PROPERTY} says: for robots that
     * bridge the Environment to Pioneer clients.
     *
     * @param host    the Environment's host
     * @param port    its robot port
     * @param options timeouts
     * @return the link
     */
    public static EnvironmentLink toEnvironment(String host, int port, HardwareOptions options) {
        Mode mode = Mode.configured();
        String key = host + ":" + port;
        int robots = ROBOTS.merge(key, 1, Integer::sum);
        Runnable released = () -> ROBOTS.computeIfPresent(key, (k, n) -> n > 1 ? n - 1 : null);
        boolean shared = mode == Mode.SHARED || mode == Mode.AUTO && robots > 1;
        return shared ? new LinkMember(host, port, options, released) : new SocketLink(host, port, options, released);
    }

    /**
     * A link to a Pioneer robot server.
     *
     * @param address the server, {@code host:port}
     * @param options timeouts
     * @return the link, not yet open
     * @throws IllegalArgumentException if the address is not {@code host:port} with a port of 1 to 65535
     */
    public static PioneerLink pioneer(String address, HardwareOptions options) {
        int colon = address.lastIndexOf(':');
        String rule = ": a Pioneer robot server is given as HOST:PORT, the port 1 to 65535";
        if (colon <= 0 || colon == address.length() - 1) {
            throw new IllegalArgumentException("'" + address + "' was supplied for the Pioneer robot server" + rule);
        }
        int port;
        try {
            port = Integer.parseInt(address.substring(colon + 1).trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("'" + address + "' was supplied for the Pioneer robot server" + rule, e);
        }
        if (port <= 0 || port > 65535) {
            throw new IllegalArgumentException("'" + address + "' was supplied for the Pioneer robot server" + rule);
        }
        return new PioneerLink(address.substring(0, colon).trim(), port, options);
    }
}
