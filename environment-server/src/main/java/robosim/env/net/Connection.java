package robosim.env.net;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.protocol.Bye;
import robosim.protocol.FrameDecoder;
import robosim.protocol.FrameWriter;
import robosim.protocol.LogLimiter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.RobotHello;
import robosim.protocol.inprocess.MessageSink;

/**
 * One peer of the Environment, robot or viewer, on a non-blocking channel served by the step
 * loop's selector: frames in through a {@link FrameDecoder}, frames out through a queue that is
 * written as the peer can take it. A peer that lets too much pile up is closed, so a slow or stuck
 * peer never blocks the run. A robot connection carries one robot, or, once it has said
 * {@link robosim.protocol.LinkHello}, is a shared link carrying the robots that said hello on it.
 * Its refusals and closes are logged through a {@link LogLimiter} shared by all of a server's
 * connections, one line per kind a second, since a peer can cause them as often as it connects;
 * only the close of a robot connection that was admitted (with the run's secret) is logged whole,
 * as it comes once for each admission, which is logged too.
 *
 * <p>An in-process connection ({@link #inProcess}) carries the same messages as objects, to a
 * {@link MessageSink} of a robot runtime in this JVM: what it sends is delivered at once, what it
 * receives comes through {@link InProcessDoor}; it has no channel, no frames and nothing queued.
 */
final class Connection {
    private static final Logger LOG = Logger.getLogger(Connection.class.getName());

    enum Kind { ROBOT, VIEWER }

    final Kind kind;
    private final SocketChannel channel;
    private final SelectionKey key;
    private final FrameDecoder decoder;
    /** Where an in-process connection's messages go; null for one over TCP. */
    private final MessageSink local;
    private final MessageCodec codec;
    private final ArrayDeque<ByteBuffer> outgoing = new ArrayDeque<>();
    private final long maxQueuedBytes;
    private final String address;
    private final LogLimiter log;
    private long queuedBytes;
    private String name;
    private boolean link;
    private final Set<String> robots = new LinkedHashSet<>();
    private boolean closed;
    private boolean closeWhenFlushed;
    private boolean control;
    private final long acceptedNanos = System.nanoTime();
    private long lastReadNanos = acceptedNanos;
    private long lastWriteNanos = acceptedNanos;

    /** A connection that logs through a limiter of its own (a test's lone connection). */
    Connection(Kind kind, SocketChannel channel, Selector selector, MessageCodec codec, int maxFrame,
               long maxQueuedBytes) throws IOException {
        this(kind, channel, selector, codec, maxFrame, maxQueuedBytes, newLog());
    }

    /**
     * @param log the limiter of the server's connections, from {@link #newLog()}
     */
    Connection(Kind kind, SocketChannel channel, Selector selector, MessageCodec codec, int maxFrame,
               long maxQueuedBytes, LogLimiter log) throws IOException {
        this.kind = kind;
        this.log = log;
        this.local = null;
        this.channel = channel;
        this.codec = codec;
        this.decoder = new FrameDecoder(codec, maxFrame);
        this.maxQueuedBytes = maxQueuedBytes;
        this.address = String.valueOf(channel.getRemoteAddress());
        channel.configureBlocking(false);
        channel.socket().setTcpNoDelay(true);
        this.key = channel.register(selector, SelectionKey.OP_READ, this);
    }

    private Connection(MessageSink robots, MessageCodec codec, LogLimiter log) {
        this.kind = Kind.ROBOT;
        this.log = log;
        this.local = robots;
        this.channel = null;
        this.key = null;
        this.codec = codec;
        this.decoder = null;
        this.maxQueuedBytes = Long.MAX_VALUE;
        this.address = "in-process";
    }

    /**
     * An in-process robot connection: a link of robots of this JVM (see {@link InProcessDoor}).
     *
     * @param robots where its messages go
     * @param codec  the server's codec
     * @param log    the limiter of the server's connections
     * @return the connection, not yet greeted
     */
    static Connection inProcess(MessageSink robots, MessageCodec codec, LogLimiter log) {
        return new Connection(robots, codec, log);
    }

    /** @return whether this connection is in-process, not over TCP */
    boolean isInProcess() {
        return local != null;
    }

    /** @return a limiter for the log lines of one server's connections */
    static LogLimiter newLog() {
        return new LogLimiter(LOG);
    }

    /**
     * @return the robot's or viewer's name once it has said hello, the link's client, else its
     *         address; a name the peer chose is escaped, so that it cannot break a log line
     */
    String peer() {
        if (link) {
            return "link of " + LogLimiter.excerpt(name) + " at " + address;
        }
        String k = control ? "control client" : kind.name().toLowerCase();
        if (name == null) {
            return k + " at " + address;
        }
        // a robot's name was checked against the rule of names; a viewer's or client's was not
        return k + " " + (kind == Kind.ROBOT ? RobotHello.printable(name) : LogLimiter.excerpt(name));
    }

    /**
     * Makes this connection a shared link of many robots.
     *
     * @param client who opened it, for the log
     */
    void becomeLink(String client) {
        link = true;
        name = String.valueOf(client);
    }

    /** @return whether this is a shared link of many robots */
    boolean isLink() {
        return link;
    }

    /** @param robot a robot the Environment welcomed on this link */
    void addRobot(String robot) {
        robots.add(robot);
    }

    /** @return the robots on this link now, in the order they joined */
    List<String> robots() {
        return new ArrayList<>(robots);
    }

    /** @return whether a robot is on this link now */
    boolean carries(String robot) {
        return robots.contains(robot);
    }

    /**
     * Ends one robot's part in a shared link, which stays open for the others: the robot is told
     * why; a reason is logged in one line naming the robot, as closing its own connection would.
     *
     * @param robot  the robot
     * @param reason why, or null for an orderly leave
     */
    void dropRobot(String robot, String reason) {
        if (!robots.remove(robot)) {
            return;
        }
        if (reason != null) {
            // once for each admission of the robot on the link, as a robot connection's own close
            LOG.warning(() -> "closing robot " + robot + ": " + reason);
        }
        send(new Bye(reason != null ? reason : Bye.GOODBYE, robot));
    }

    /** Ends one robot's part on a shared link quietly: its run ended, and the bye says so. */
    void endRobot(String robot, String reason) {
        if (robots.remove(robot)) {
            send(new Bye(reason, robot));
        }
    }

    void setName(String name) {
        this.name = name;
    }

    /** Makes this viewer-port connection a control client, which may change the run. */
    void becomeControl() {
        control = true;
    }

    /** @return whether this is a control client */
    boolean isControl() {
        return control;
    }

    /** @return whether the peer has said a hello that was accepted: it has a name, or is a link */
    boolean greeted() {
        return name != null;
    }

    /** @return when the connection was accepted, {@link System#nanoTime()} */
    long acceptedNanos() {
        return acceptedNanos;
    }

    /** @return when a frame's bytes last arrived from the peer, {@link System#nanoTime()} */
    long lastReadNanos() {
        return lastReadNanos;
    }

    /**
     * @return when the peer last took some of what is queued for it, or since when nothing has been
     *         queued, {@link System#nanoTime()}
     */
    long lastWriteNanos() {
        return lastWriteNanos;
    }

    /** @return bytes queued for the peer and not yet written */
    long queuedBytes() {
        return queuedBytes;
    }

    /** @return the peer's address */
    String address() {
        return address;
    }

    String name() {
        return name;
    }

    boolean isClosed() {
        return closed;
    }


    /**
     * Reads what has arrived.
     *
     * @param buffer scratch space shared by all connections
     * @return the messages completed, or null at the end of the stream
     * @throws IOException if reading fails or a frame breaks the rules
     */
    List<Message> read(ByteBuffer buffer) throws IOException {
        buffer.clear();
        int n = channel.read(buffer);
        if (n < 0) {
            if (decoder.midFrame()) {
                throw new IOException("the stream ended inside a frame");
            }
            return null;
        }
        if (n > 0) {
            lastReadNanos = System.nanoTime();
        }
        buffer.flip();
        return decoder.decode(buffer);
    }

    /** Queues a message and writes what the peer can take now. */
    void send(Message m) {
        if (closed || closeWhenFlushed) {
            return;
        }
        if (local != null) {
            local.deliver(m);
            return;
        }
        sendFrame(FrameWriter.frame(codec, m));
    }

    /**
     * Sends a message encoded once for many peers: a peer over TCP is queued the frame (pass each
     * its duplicate), an in-process one takes the message itself.
     *
     * @param m     the message
     * @param frame its frame, or null for an in-process peer, which needs none
     */
    void send(Message m, ByteBuffer frame) {
        if (local != null) {
            send(m);
        } else {
            sendFrame(frame);
        }
    }

    /**
     * Queues a frame already encoded (the same frame can go to many peers: pass each a duplicate)
     * and writes what the peer, one over TCP, can take now.
     */
    void sendFrame(ByteBuffer frame) {
        if (closed || closeWhenFlushed) {
            return;
        }
        if (outgoing.isEmpty()) {
            lastWriteNanos = System.nanoTime();
        }
        queuedBytes += frame.remaining();
        outgoing.add(frame);
        try {
            // what the peer takes now does not count against it: only what stays queued does
            writable();
        } catch (IOException e) {
            close("write failed: " + e.getMessage());
            return;
        }
        if (queuedBytes > limit()) {
            close("it fell " + queuedBytes + " bytes behind (the limit is " + limit() + ")");
        }
    }

    /** @return how far the peer may fall behind: for a shared link, its robots' share each */
    private long limit() {
        return link ? maxQueuedBytes * Math.max(1, (robots.size() + 99) / 100) : maxQueuedBytes;
    }

    /**
     * Refuses a peer that has not been admitted: one log line naming it and the reason, a
     * {@link Bye} with the reason, and the connection closes once that is written.
     *
     * @param reason why
     */
    void refuse(String reason) {
        log.warning("refused connections on the " + port() + " port", () -> "refusing " + peer() + ": " + reason);
        sendAndClose(new Bye(Bye.REFUSED + reason));
    }

    /** Sends a last message, then closes once it is written. */
    void sendAndClose(Message m) {
        send(m);
        closeWhenFlushed = true;
        if (outgoing.isEmpty() || local != null) {
            shut();
        }
    }

    /**
     * Writes queued frames until the peer can take no more.
     *
     * @throws IOException if writing fails
     */
    void writable() throws IOException {
        while (!outgoing.isEmpty()) {
            ByteBuffer b = outgoing.peek();
            int n = channel.write(b);
            queuedBytes -= n;
            if (n > 0) {
                lastWriteNanos = System.nanoTime();
            }
            if (b.hasRemaining()) {
                key.interestOps(SelectionKey.OP_READ | SelectionKey.OP_WRITE);
                return;
            }
            outgoing.poll();
        }
        if (closeWhenFlushed) {
            shut();
        } else if (key.isValid()) {
            key.interestOps(SelectionKey.OP_READ);
        }
    }

    /** Closes at once, logging one line that names the peer and the reason. */
    void close(String reason) {
        if (closed) {
            return;
        }
        if (kind == Kind.ROBOT && greeted()) {
            LOG.warning(() -> "closing " + peer() + ": " + reason);
        } else {
            log.warning("closed " + role(), () -> "closing " + peer() + ": " + reason);
        }
        shut();
    }

    /** @return the port the connection came on, for a kind of log line */
    private String port() {
        return kind == Kind.ROBOT ? "robot" : "viewer";
    }

    /** @return what the peer is, plural, for a kind of log line: fixed words, never the peer's */
    private String role() {
        if (control) {
            return "control connections";
        }
        return name != null ? port() + " connections" : "connections without a hello on the " + port() + " port";
    }

    /** Closes without a word: an orderly end. */
    void shut() {
        if (closed) {
            return;
        }
        closed = true;
        outgoing.clear();
        if (local != null) {
            local.closed("the Environment closed the link");
            return;
        }
        key.cancel();
        try {
            channel.close();
        } catch (IOException e) {
            LOG.log(Level.FINE, "closing " + peer(), e);
        }
    }
}
