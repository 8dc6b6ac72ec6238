package robosim.env.net;

import java.io.IOException;
import java.net.Socket;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.protocol.Bye;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;

/**
 * One peer of the Environment, robot or viewer: a reader thread that turns frames into
 * {@link ServerEvent}s on the server's queue, and a writer thread that drains an outgoing queue, so
 * that a slow or stuck peer never blocks the step loop.
 */
final class Connection {
    private static final Logger LOG = Logger.getLogger(Connection.class.getName());
    private static final Message CLOSE = new Bye("close");

    enum Kind { ROBOT, VIEWER }

    final Kind kind;
    private final Socket socket;
    private final BlockingQueue<ServerEvent> events;
    private final BlockingQueue<Message> outgoing = new LinkedBlockingQueue<>();
    private final FrameReader reader;
    private final FrameWriter writer;
    private final int maxQueued;
    private volatile String name;
    private volatile boolean closed;
    private final CountDownLatch writerDone = new CountDownLatch(1);

    Connection(Kind kind, Socket socket, BlockingQueue<ServerEvent> events, MessageCodec codec, int maxFrame,
               int maxQueued) throws IOException {
        this.kind = kind;
        this.socket = socket;
        this.events = events;
        this.maxQueued = maxQueued;
        socket.setTcpNoDelay(true);
        this.reader = new FrameReader(socket.getInputStream(), codec, maxFrame);
        this.writer = new FrameWriter(socket.getOutputStream(), codec);
    }

    void start() {
        String peer = socket.getRemoteSocketAddress().toString();
        Thread r = new Thread(this::readLoop, "env-read-" + peer);
        Thread w = new Thread(this::writeLoop, "env-write-" + peer);
        r.setDaemon(true);
        w.setDaemon(true);
        r.start();
        w.start();
    }

    /** @return the robot's or viewer's name once it has said hello, else its address */
    String peer() {
        String n = name;
        return n != null ? kind.name().toLowerCase() + " " + n : kind.name().toLowerCase() + " at " + socket.getRemoteSocketAddress();
    }

    void setName(String name) {
        this.name = name;
    }

    String name() {
        return name;
    }

    boolean isClosed() {
        return closed;
    }

    /** Queues a message; a peer that lets too many pile up is closed. */
    void send(Message m) {
        if (closed) {
            return;
        }
        if (outgoing.size() >= maxQueued) {
            close("it fell " + maxQueued + " messages behind");
            return;
        }
        outgoing.add(m);
    }

    /** Sends a last message, then closes once it is written. */
    void sendAndClose(Message m) {
        if (!closed) {
            outgoing.add(m);
            outgoing.add(CLOSE);
        }
    }

    /** Closes at once, logging one line that names the peer and the reason. */
    void close(String reason) {
        if (closed) {
            return;
        }
        closed = true;
        LOG.warning(() -> "closing " + peer() + ": " + reason);
        shut();
    }

    private void shut() {
        closed = true;
        outgoing.clear();
        outgoing.add(CLOSE);
        try {
            socket.close();
        } catch (IOException e) {
            LOG.log(Level.FINE, "closing socket", e);
        }
    }

    /** Waits, bounded, until everything queued has been written. */
    void awaitWritten(long timeoutMs) {
        try {
            writerDone.await(timeoutMs, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void readLoop() {
        String reason = "it disconnected";
        try {
            Message m;
            while ((m = reader.read()) != null) {
                events.add(new ServerEvent.Received(this, m));
            }
        } catch (IOException e) {
            reason = closed ? "closed" : e.getMessage();
        }
        events.add(new ServerEvent.Closed(this, reason));
    }

    private void writeLoop() {
        try {
            while (true) {
                Message m = outgoing.take();
                if (m == CLOSE) {
                    break;
                }
                writer.write(m);
            }
        } catch (IOException e) {
            if (!closed) {
                events.add(new ServerEvent.Closed(this, "write failed: " + e.getMessage()));
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        closed = true;
        writerDone.countDown();
        try {
            socket.shutdownOutput();
        } catch (IOException e) {
            LOG.log(Level.FINE, "shutting output", e);
        }
    }
}
