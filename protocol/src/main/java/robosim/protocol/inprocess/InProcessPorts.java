package robosim.protocol.inprocess;

import java.io.IOException;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The Environments of this JVM that robots of this JVM may reach without TCP: an Environment
 * registers its robot port here, and a robot whose runtime chooses in-process links and that
 * connects to a loopback address and that port opens its link through the registered
 * {@link Acceptor} instead of a socket. Messages then go both ways as objects
 * ({@link MessageSink}), with no encoding, no system call and no frame; everything else (the
 * hello, the welcome, the lockstep, the bye) is as over TCP.
 */
public final class InProcessPorts {
    /** The host names that mean this machine, for which a registered port is found. */
    private static final Set<String> LOOPBACK = Set.of("127.0.0.1", "localhost", "::1", "0:0:0:0:0:0:0:1");
    private static final Map<Integer, Acceptor> PORTS = new ConcurrentHashMap<>();

    private InProcessPorts() {
    }

    /** An Environment's side of in-process links: it opens one for each robot runtime that asks. */
    @FunctionalInterface
    public interface Acceptor {
        /**
         * Opens a link, as accepting a connection would.
         *
         * @param toRobots where the Environment's messages for the link go
         * @return where the link's messages for the Environment go
         * @throws IOException if the Environment is closed
         */
        MessageSink open(MessageSink toRobots) throws IOException;
    }

    /** A port's registration: closing it takes the port out of the registry. */
    public interface Registration extends AutoCloseable {
        @Override
        void close();
    }

    /**
     * Registers an Environment's robot port.
     *
     * @param port     the robot port it listens on
     * @param acceptor opens its in-process links
     * @return the registration, to close when the Environment closes
     * @throws IllegalStateException if an Environment of this JVM has registered that port already
     */
    public static Registration register(int port, Acceptor acceptor) {
        if (PORTS.putIfAbsent(port, acceptor) != null) {
            throw new IllegalStateException("port " + port + " was supplied for an in-process Environment: another"
                    + " Environment of this JVM has it");
        }
        return () -> PORTS.remove(port, acceptor);
    }

    /**
     * @param host the host a robot was told to connect to
     * @param port the port
     * @return the acceptor of the Environment of this JVM at that address, if the host is a loopback
     *         address and an Environment registered the port
     */
    public static Optional<Acceptor> find(String host, int port) {
        if (host == null || !LOOPBACK.contains(host.trim().toLowerCase(Locale.ROOT))) {
            return Optional.empty();
        }
        return Optional.ofNullable(PORTS.get(port));
    }
}
