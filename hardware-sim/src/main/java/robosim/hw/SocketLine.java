package robosim.hw;

import java.io.IOException;
import java.net.Socket;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;

/** A {@link MessageLine} over TCP: frames of the wire's codec, read with the link's lost time as timeout. */
final class SocketLine implements MessageLine {
    private static final Logger LOG = Logger.getLogger(SocketLine.class.getName());
    private final Socket socket;
    private final FrameReader reader;
    private final FrameWriter writer;

    private SocketLine(Socket socket) throws IOException {
        this.socket = socket;
        this.reader = new FrameReader(socket.getInputStream(), SocketLink.CODEC, FrameReader.DEFAULT_MAX_FRAME);
        this.writer = new FrameWriter(socket.getOutputStream(), SocketLink.CODEC);
    }

    /**
     * Connects, trying again while nothing listens until the connect timeout.
     *
     * @param host    the Environment's host
     * @param port    its robot port
     * @param options timeouts
     * @return the line
     * @throws IOException if it cannot connect
     */
    static SocketLine connect(String host, int port, HardwareOptions options) throws IOException {
        Socket socket = SocketLink.connectSocket(host, port, options);
        try {
            socket.setSoTimeout((int) options.lostAfterMs());
            return new SocketLine(socket);
        } catch (IOException | RuntimeException e) {
            socket.close();
            throw e;
        }
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
