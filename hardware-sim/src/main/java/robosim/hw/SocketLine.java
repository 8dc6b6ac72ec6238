package robosim.hw;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;

/** A {@link MessageLine} over TCP: frames of the wire's codec, read with the link's lost time as timeout. */
final class SocketLine implements MessageLine {
    private static final Logger LOG = Logger.getLogger(SocketLine.class.getName());
    private static final long RETRY_MS = 200;
    /** One codec for every link of the JVM: Jackson's mapper is thread-safe, and costly to warm. */
    static final MessageCodec CODEC = new MessageCodec();
    private final Socket socket;
    private final FrameReader reader;
    private final FrameWriter writer;

    private SocketLine(Socket socket) throws IOException {
        this.socket = socket;
        this.reader = new FrameReader(socket.getInputStream(), CODEC, FrameReader.DEFAULT_MAX_FRAME);
        this.writer = new FrameWriter(socket.getOutputStream(), CODEC);
    }

    /**
     * Connects, trying again while nothing listens until the connect timeout; a read gives up
     * after the link's lost time.
     *
     * @param host    the Environment's host
     * @param port    its robot port
     * @param options timeouts
     * @return the line
     * @throws IOException if it cannot connect
     */
    static SocketLine connect(String host, int port, HardwareOptions options) throws IOException {
        return connect(host, port, options, options.lostAfterMs());
    }

    /**
     * Connects as {@link #connect(String, int, HardwareOptions)} does, a read giving up after
     * {@code readTimeoutMs} until {@link #readTimeout} says otherwise.
     */
    static SocketLine connect(String host, int port, HardwareOptions options, long readTimeoutMs) throws IOException {
        Socket socket = connectSocket(host, port, options);
        try {
            socket.setSoTimeout((int) readTimeoutMs);
            return new SocketLine(socket);
        } catch (IOException | RuntimeException e) {
            socket.close();
            throw e;
        }
    }

    /**
     * Connects, trying again while nothing listens (the Environment may still be starting) until
     * the connect timeout.
     */
    private static Socket connectSocket(String host, int port, HardwareOptions options) throws IOException {
        long deadline = System.currentTimeMillis() + options.connectTimeoutMs();
        while (true) {
            Socket socket = new Socket();
            try {
                socket.connect(new InetSocketAddress(host, port), (int) options.connectTimeoutMs());
                socket.setTcpNoDelay(true);
                return socket;
            } catch (ConnectException e) {
                socket.close();
                if (System.currentTimeMillis() + RETRY_MS > deadline) {
                    throw new ConnectException("no Environment at " + host + ":" + port + " within "
                            + options.connectTimeoutMs() + " ms (" + e.getMessage() + ")");
                }
                try {
                    Thread.sleep(RETRY_MS);
                } catch (InterruptedException ie) {
                    Thread.currentThread().interrupt();
                    throw new IOException("interrupted while connecting", ie);
                }
            }
        }
    }

    /**
     * @param ms how long a read waits for a byte before it gives up
     * @throws IOException if the socket is closed
     */
    void readTimeout(long ms) throws IOException {
        socket.setSoTimeout((int) ms);
    }

    @Override
    public Message read() throws IOException {
        return reader.read();
    }

    @Override
    public void write(Message message) throws IOException {
        writer.write(message);
    }

    @Override
    public void close() {
        try {
            socket.close();
        } catch (IOException e) {
            LOG.log(Level.FINE, "closing", e);
        }
    }
}
