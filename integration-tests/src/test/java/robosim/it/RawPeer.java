package robosim.it;

import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.Socket;
import java.net.SocketTimeoutException;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;

/** A hand-driven peer on a raw socket, to send the Environment what a real client never would. */
final class RawPeer implements AutoCloseable {
    final Socket socket;
    final FrameWriter writer;
    final FrameReader reader;

    RawPeer(int port) throws IOException {
        socket = new Socket("127.0.0.1", port);
        socket.setSoTimeout(20_000);
        MessageCodec codec = new MessageCodec();
        writer = new FrameWriter(socket.getOutputStream(), codec);
        reader = new FrameReader(socket.getInputStream(), codec, 1 << 24);
    }

    void send(Message m) throws IOException {
        writer.write(m);
    }

    Message read() throws IOException {
        return reader.read();
    }

    void sendRaw(byte[] bytes) throws IOException {
        DataOutputStream out = new DataOutputStream(socket.getOutputStream());
        out.write(bytes);
        out.flush();
    }

    /** Reads until the Environment closes the connection; fails if it stays open 20 s. */
    boolean closedByPeer() throws IOException {
        InputStream in = socket.getInputStream();
        try {
            byte[] buf = new byte[4096];
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
