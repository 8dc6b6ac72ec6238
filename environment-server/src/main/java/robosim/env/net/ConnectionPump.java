package robosim.env.net;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.ServerSocketChannel;
import java.util.Iterator;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import robosim.protocol.InvalidValueException;
import robosim.protocol.Message;

/**
 * The step loop's one selector, part of {@link EnvironmentServer}: accepts peers, reads what they
 * sent and hands it to the {@link SessionRules}, writes what waits for them, and keeps the robots
 * alive, all on the step loop's thread between (and while waiting inside) steps.
 */
final class ConnectionPump implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(EnvironmentServer.class.getName());

    private final Doorway doorway;
    private final SessionRules rules;
    private final ProgressReports progress;
    private final TimeStepSender sender;
    private final ByteBuffer readBuffer = ByteBuffer.allocateDirect(1 << 16);
    private Selector selector;

    ConnectionPump(Doorway doorway, SessionRules rules, ProgressReports progress, TimeStepSender sender) {
        this.doorway = doorway;
        this.rules = rules;
        this.progress = progress;
        this.sender = sender;
    }

    /** Opens the selector and both listening sockets. */
    void bind() throws IOException {
        selector = Selector.open();
        doorway.bind(selector);
    }

    /** Serves every ready connection once, waiting until something is ready or the deadline. */
    void pump(long deadlineNanos) throws InterruptedException {
        long now = System.nanoTime();
        // wake for the progress when it is due, while waiting for robots or a held step
        long nextCheck = progress.wakeBy(now, doorway.check(now));
        long waitMs = Math.max(1, TimeUnit.NANOSECONDS.toMillis(Math.min(deadlineNanos, nextCheck) - now));
        InProcessDoor local = doorway.inProcess();
        try {
            if (local.mayWait()) {
                selector.select(waitMs);
                local.awake();
            } else {
                selector.selectNow();
            }
        } catch (IOException e) {
            throw new UncheckedIOException("the selector failed", e);
        }
        if (Thread.interrupted()) {
            throw new InterruptedException();
        }
        local.drain(doorway::adopt, rules::received, c -> {
            rules.closed(c, SessionRules.DISCONNECTED);
            c.shut();
        });
        Iterator<SelectionKey> it = selector.selectedKeys().iterator();
        while (it.hasNext()) {
            SelectionKey key = it.next();
            it.remove();
            if (!key.isValid()) {
                continue;
            }
            if (key.isAcceptable()) {
                doorway.accept((ServerSocketChannel) key.channel(), (Connection.Kind) key.attachment());
            } else {
                serve((Connection) key.attachment(), key);
            }
        }
        doorway.served();
        rules.log().forward(rules.sim().stepCount());
        sender.keepAlive(rules.sim().stepCount(), doorway.connections());
    }

    private void serve(Connection c, SelectionKey key) {
        try {
            if (key.isWritable()) {
                c.writable();
            }
            if (key.isValid() && key.isReadable()) {
                List<Message> messages = c.read(readBuffer);
                if (messages == null) {
                    rules.closed(c, SessionRules.DISCONNECTED);
                    return;
                }
                for (Message m : messages) {
                    rules.received(c, m);
                }
            }
        } catch (InvalidValueException e) {
            rules.invalid(c, e.getMessage());
        } catch (IOException e) {
            rules.failed(c, e);
            c.close(e.getMessage());
        }
    }

    /** Closes every connection, the listening sockets and the selector. */
    @Override
    public void close() {
        doorway.close();
        if (selector != null) {
            try {
                selector.close();
            } catch (IOException e) {
                LOG.fine("closing: " + e.getMessage());
            }
        }
    }
}
