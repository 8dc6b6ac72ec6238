package robosim.hw;

import java.io.IOException;
import java.net.SocketTimeoutException;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import robosim.protocol.Message;
import robosim.protocol.inprocess.InProcessPorts;
import robosim.protocol.inprocess.MessageSink;

/**
 * A {@link MessageLine} to an Environment of this JVM ({@link InProcessPorts}): the Environment's
 * messages wait in a queue for the link's reader, and the link's go straight into the
 * Environment's, as objects. Nothing is encoded, and no system call stands between the two.
 */
final class InProcessLine implements MessageLine, MessageSink {
    /** Put in the queue when the Environment closed the line: the reader sees the end. */
    private static final Object END = new Object();
    private final BlockingQueue<Object> inbox = new LinkedBlockingQueue<>();
    private final long lostAfterMs;
    private volatile MessageSink toEnvironment;
    private volatile boolean closed;

    private InProcessLine(long lostAfterMs) {
        this.lostAfterMs = lostAfterMs;
    }

    /**
     * Opens a line to an Environment of this JVM.
     *
     * @param environment the Environment's acceptor
     * @param options     the lost time
     * @return the line
     * @throws IOException if the Environment has closed
     */
    static InProcessLine open(InProcessPorts.Acceptor environment, HardwareOptions options) throws IOException {
        InProcessLine line = new InProcessLine(options.lostAfterMs());
        line.toEnvironment = environment.open(line);
        return line;
    }

    @Override
    public Message read() throws IOException {
        Object next;
        try {
            next = inbox.poll(lostAfterMs, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while waiting for the Environment", e);
        }
        if (next == null) {
            throw new SocketTimeoutException("nothing came for " + lostAfterMs + " ms");
        }
        if (next == END) {
            inbox.add(END); // a second read sees the end too
            return null;
        }
        return (Message) next;
    }

    @Override
    public void write(Message message) throws IOException {
        if (closed) {
            throw new IOException("the in-process link is closed");
        }
        toEnvironment.deliver(message);
    }

    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        toEnvironment.closed("the robots' runtime closed the link");
        inbox.add(END);
    }

    @Override
    public void deliver(Message message) {
        inbox.add(message);
    }

    @Override
    public void closed(String reason) {
        closed = true;
        inbox.add(END);
    }
}
