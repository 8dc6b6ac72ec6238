package robosim.hw;

import java.util.Locale;
import java.util.Optional;
import robosim.protocol.inprocess.InProcessPorts;

/**
 * Chooses each robot's {@link EnvironmentLink}, as its {@link RobotRuntime}'s choices say. By
 * default ({@code auto}) a robot alone in its runtime has a connection of its own, with one frame
 * per robot each way each step, as every robot had before shared links; from the second robot of a
 * runtime connected to the same Environment on, the robots share one connection, each step's states
 * arriving in one frame and their requests leaving in one. Runs are the same either way: the
 * Environment steps each robot as it would over a connection of its own.
 *
 * <p>An Environment of the same JVM that admits robots in-process
 * ({@link robosim.protocol.inprocess.InProcessPorts}) is reached, by default, without TCP: every
 * robot of the runtime on one in-process link, the same messages as objects, nothing encoded.
 *
 * <p>The links chosen can be {@code own}, a connection of its own for every robot, or
 * {@code shared}, every robot, the first too, on the shared one: both over TCP, even to an
 * Environment of the same JVM. The default runtime takes the choice from the system property
 * {@value #PROPERTY}.
 *
 * <p>A runtime may send its robots to a Pioneer robot server's {@code host:port} instead (the default
 * runtime when the system property {@value #PIONEER_PROPERTY} names one), through a
 * {@link PioneerLink}: the same program then drives MobileSim, a real Pioneer behind a
 * serial-to-TCP bridge, or RoboSim's own Pioneer port, whatever Environment host and port it was
 * given.
 */
public final class EnvironmentLinks {
    /** The system property that chooses the default runtime's links. */
    public static final String PROPERTY = "robosim.link";
    /** The system property that sends the default runtime's robots to a Pioneer robot server, {@code host:port}. */
    public static final String PIONEER_PROPERTY = "robosim.pioneer";

    private EnvironmentLinks() {
    }

    /** How robots reach the Environment. */
    public enum Mode {
        /**
         * The first robot of a runtime alone, the others sharing one connection; every robot on
         * one in-process link to an Environment of this JVM that admits robots so.
         */
        AUTO,
        /** A connection for each robot. */
        OWN,
        /** One connection for every robot of the runtime. */
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
     * A link for one robot of a runtime, not yet open, as the runtime's choices say.
     *
     * @param runtime the runtime the robot uses, open
     * @param host    the Environment's host
     * @param port    its robot port
     * @param options timeouts
     * @return the link
     */
    static EnvironmentLink to(RobotRuntime runtime, String host, int port, HardwareOptions options) {
        String pioneer = runtime.choices().pioneer();
        if (pioneer != null) {
            PioneerLink server = pioneer(pioneer, options);
            return new PioneerLink(server.host(), server.port(), options, runtime.choices().virtualThreads());
        }
        return toEnvironment(runtime, host, port, options);
    }

    /**
     * A link to the Environment itself, whatever Pioneer robot server the runtime names: for robots
     * that bridge the Environment to Pioneer clients.
     *
     * @param runtime the runtime the robot uses, open
     * @param host    the Environment's host
     * @param port    its robot port
     * @param options timeouts
     * @return the link
     */
    static EnvironmentLink toEnvironment(RobotRuntime runtime, String host, int port, HardwareOptions options) {
        Mode mode = runtime.choices().links();
        String key = host + ":" + port;
        int robots = runtime.countRobotAt(key);
        Runnable released = () -> runtime.uncountRobotAt(key);
        boolean shared = mode == Mode.SHARED || mode == Mode.AUTO && robots > 1
                || inProcess(runtime, host, port).isPresent();
        return shared ? new LinkMember(runtime, host, port, options, released)
                : new SocketLink(runtime, host, port, options, released);
    }

    /**
     * @param runtime the runtime whose robot connects
     * @param host    the Environment's host
     * @param port    its robot port
     * @return the Environment of this JVM at {@code host:port} that admits robots in-process, if there
     *         is one and the runtime leaves the choice to it ({@link Mode#AUTO}): its robots then reach
     *         it on one in-process link
     */
    static Optional<InProcessPorts.Acceptor> inProcess(RobotRuntime runtime, String host, int port) {
        return runtime.choices().links() == Mode.AUTO ? InProcessPorts.find(host, port) : Optional.empty();
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
