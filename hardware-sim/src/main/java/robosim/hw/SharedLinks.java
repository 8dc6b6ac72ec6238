package robosim.hw;

import java.io.IOException;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;
import robosim.protocol.inprocess.InProcessPorts;

/**
 * The {@link SharedLink}s of one {@link RobotRuntime}, one per Environment, and the threads that hand
 * the robots of a large frame their states, shared by its links.
 */
final class SharedLinks {
    private final RobotRuntime runtime;
    /** The open links, by the Environment's host and port. */
    private final Map<String, SharedLink> open = new ConcurrentHashMap<>();
    /** Held while a link connects, so that robots connecting together open one link. */
    private final Object connecting = new Object();
    /** One thread per processor (none on one processor), made when a frame first needs them; guarded by this. */
    private ExecutorService handers;

    /** @param runtime the runtime the links belong to */
    SharedLinks(RobotRuntime runtime) {
        this.runtime = runtime;
    }

    /**
     * The runtime's open link to an Environment, connected if none is open.
     *
     * @param host    the Environment's host
     * @param port    its robot port
     * @param options timeouts (the first robot's serve the whole link)
     * @param secret  gives the run secret the link presents once connected (the opening robot's)
     * @return the link
     * @throws IOException if it cannot connect
     */
    SharedLink to(String host, int port, HardwareOptions options, Supplier<String> secret) throws IOException {
        String key = host + ":" + port;
        synchronized (connecting) {
            SharedLink link = open.get(key);
            if (link == null || link.hasEnded()) {
                link = new SharedLink(this, host, port, options, secret, line(host, port, options));
                open.put(key, link);
                runtime.readerThread("hw-link-" + runtime.name() + "-" + key, link::read).start();
            }
            return link;
        }
    }

    /**
     * @return a line to the Environment at {@code host:port}: in-process if that Environment runs in
     *         this JVM and admits robots so, and the runtime leaves the choice to it ({@code auto});
     *         else over TCP
     */
    private MessageLine line(String host, int port, HardwareOptions options) throws IOException {
        Optional<InProcessPorts.Acceptor> local = EnvironmentLinks.inProcess(runtime, host, port);
        return local.isPresent() ? InProcessLine.open(local.get(), options) : SocketLine.connect(host, port, options);
    }

    /** Sends, on every open link, the requests of robots that are ready when others are late. */
    void sendLingering() {
        long now = System.nanoTime();
        for (SharedLink link : open.values()) {
            link.sendLingering(now);
        }
    }

    /** A link ended: a later robot opens a new one. */
    void ended(SharedLink link) {
        open.remove(link.environment(), link);
    }

    /** @return the threads that hand out a large frame's states, or null on one processor */
    synchronized ExecutorService handers() {
        int processors = Runtime.getRuntime().availableProcessors();
        if (handers == null && processors >= 2) {
            AtomicInteger made = new AtomicInteger();
            handers = Executors.newFixedThreadPool(processors, r -> {
                Thread t = new Thread(r, "hw-link-hand-" + runtime.name() + "-" + made.incrementAndGet());
                t.setDaemon(true);
                return t;
            });
        }
        return handers;
    }

    /**
     * Closes every open link and stops the handing threads: the runtime's last robot has left.
     *
     * @param reason why, for the links' log
     */
    void closeAll(String reason) {
        for (SharedLink link : List.copyOf(open.values())) {
            link.close(reason);
        }
        ExecutorService stopping;
        synchronized (this) {
            stopping = handers;
            handers = null;
        }
        if (stopping != null) {
            stopping.shutdown();
        }
    }

    /** @return how many links are open */
    int openCount() {
        return open.size();
    }
}
