package robosim.env.net;

import java.io.IOException;
import java.nio.channels.Selector;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import robosim.protocol.LogLimiter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.inprocess.InProcessPorts;
import robosim.protocol.inprocess.MessageSink;

/**
 * The Environment's door for robots of its own JVM ({@link InProcessPorts}): each link a robot
 * runtime opens becomes an in-process {@link Connection}, and what the runtime sends on it waits in
 * one queue until the step loop's thread takes it ({@link #drain}), as it reads what arrived on a
 * socket. A runtime's thread that adds to the queue wakes the step loop only if it is asleep in its
 * selector, so a step costs one wake-up at most, not one per message.
 */
final class InProcessDoor implements InProcessPorts.Acceptor {
    /** What a link did: opened, sent a message, or closed (no message). */
    private record Arrival(Connection connection, Message message, boolean opened) {
    }

    private final Queue<Arrival> arrivals = new ConcurrentLinkedQueue<>();
    private final MessageCodec codec;
    private final LogLimiter log;
    private volatile Selector selector;
    /** Whether the step loop is in (or about to enter) its selector's wait. */
    private volatile boolean sleeping;
    private volatile boolean closed;
    private final AtomicInteger opened = new AtomicInteger();

    InProcessDoor(MessageCodec codec, LogLimiter log) {
        this.codec = codec;
        this.log = log;
    }

    /** @param selector the step loop's selector, which a link's message wakes */
    void bind(Selector selector) {
        this.selector = selector;
    }

    @Override
    public MessageSink open(MessageSink toRobots) throws IOException {
        if (closed) {
            throw new IOException("the Environment has closed");
        }
        Connection c = Connection.inProcess(toRobots, codec, log);
        opened.incrementAndGet();
        arrive(new Arrival(c, null, true));
        return new MessageSink() {
            @Override
            public void deliver(Message message) {
                arrive(new Arrival(c, message, false));
            }

            @Override
            public void closed(String reason) {
                arrive(new Arrival(c, null, false));
            }
        };
    }

    private void arrive(Arrival a) {
        arrivals.add(a);
        // the loop sets sleeping before it looks at the queue a last time: it sees this arrival, or is woken
        if (sleeping) {
            sleeping = false;
            Selector s = selector;
            if (s != null) {
                s.wakeup();
            }
        }
    }

    /**
     * Says the step loop is about to wait in its selector.
     *
     * @return whether it may wait: false if something arrived meanwhile, to take at once
     */
    boolean mayWait() {
        sleeping = true;
        if (arrivals.isEmpty()) {
            return true;
        }
        sleeping = false;
        return false;
    }

    /** The step loop is awake again. */
    void awake() {
        sleeping = false;
    }

    /**
     * Takes everything that arrived, in order, on the step loop's thread.
     *
     * @param opened   a new link: the Environment adopts its connection
     * @param received a message on a link
     * @param ended    a link that its runtime closed
     */
    void drain(Consumer<Connection> opened, BiConsumer<Connection, Message> received, Consumer<Connection> ended) {
        Arrival a;
        while ((a = arrivals.poll()) != null) {
            if (a.opened()) {
                opened.accept(a.connection());
            } else if (a.message() != null) {
                if (!a.connection().isClosed()) {
                    received.accept(a.connection(), a.message());
                }
            } else if (!a.connection().isClosed()) {
                ended.accept(a.connection());
            }
        }
    }

    /** @return how many in-process links robot runtimes have opened so far */
    int opened() {
        return opened.get();
    }

    /** Refuses links from now on; the connections already open close with the Environment's. */
    void close() {
        closed = true;
    }
}
