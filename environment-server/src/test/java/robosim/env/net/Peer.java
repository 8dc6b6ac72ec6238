package robosim.env.net;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.ByteBuffer;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;

/**
 * A robot's or viewer's end of a loopback connection: a blocking socket speaking frames, and the
 * Environment's {@link Connection} to it.
 */
final class Peer implements AutoCloseable {
    private final Socket socket;
    private final FrameWriter writer;
    private final FrameReader reader;
    /** The Environment's end. */
    Connection connection;

    Peer(int port, MessageCodec codec, int receiveBytes) throws IOException {
        socket = new Socket();
        if (receiveBytes > 0) {
            socket.setReceiveBufferSize(receiveBytes);
        }
        socket.connect(new InetSocketAddress("127.0.0.1", port), (int) Loopback.WAIT_MS);
        socket.setSoTimeout((int) Loopback.WAIT_MS);
        writer = new FrameWriter(socket.getOutputStream(), codec);
        reader = new FrameReader(socket.getInputStream(), codec, 1 << 24);
    }

    void send(Message m) throws IOException {
        writer.write(m);
    }

    /** Sends a payload as one frame, whatever it holds. */
    void sendFrame(byte[] payload) throws IOException {
        sendRaw(ByteBuffer.allocate(4 + payload.length).putInt(payload.length).put(payload).array());
    }

    void sendRaw(byte[] bytes) throws IOException {
        OutputStream out = socket.getOutputStream();
        out.write(bytes);
        out.flush();
    }

    /** @return the next message, or null if the Environment ended the stream cleanly */
    Message read() throws IOException {
        return reader.read();
    }

    /** Reads until the Environment closes the connection; false if it stays open the whole wait. */
    boolean closedByEnvironment() throws IOException {
        InputStream in = socket.getInputStream();
        byte[] buf = new byte[1 << 16];
        try {
            while (in.read(buf) >= 0) {
                // drain whatever was queued before the close
            }
            return true;
        } catch (SocketTimeoutException e) {
            return false;
        } catch (IOException e) {
            return true;
        }
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}
