package robosim.env.net;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import robosim.protocol.FrameReader;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;

/**
 * The Environment's side of connections on 127.0.0.1, as the step loop has it: one selector, and
 * for each peer a {@link Connection} on a non-blocking channel. The peers are blocking sockets (see
 * {@link Peer}). Every wait is bounded; closing it closes every channel and the selector.
 */
final class Loopback implements AutoCloseable {
    /** How long any wait lasts before the test fails. */
    static final long WAIT_MS = 10_000;

    final MessageCodec codec = new MessageCodec();
    private final Selector selector;
    private final ServerSocketChannel server;
    private final ByteBuffer readBuffer = ByteBuffer.allocateDirect(1 << 16);
    private final List<Peer> peers = new ArrayList<>();

    Loopback() throws IOException {
        selector = Selector.open();
        server = ServerSocketChannel.open();
        server.bind(new InetSocketAddress(InetAddress.getByName("127.0.0.1"), 0));
    }

    /** Connects a peer whose Connection may fall the robot's 1 MiB behind. */
    Peer connect(Connection.Kind kind) throws IOException {
        return connect(kind, 1 << 20, 0);
    }

    /**
     * @param maxQueued        how far the Connection may fall behind, bytes
     * @param peerReceiveBytes the peer's socket receive buffer, or 0 for the system's
     */
    Peer connect(Connection.Kind kind, long maxQueued, int peerReceiveBytes) throws IOException {
        Peer peer = new Peer(server.socket().getLocalPort(), codec, peerReceiveBytes);
        peers.add(peer);
        SocketChannel ch = server.accept();
        peer.connection = new Connection(kind, ch, selector, codec, FrameReader.DEFAULT_MAX_FRAME, maxQueued);
        return peer;
    }

    /**
     * Waits until the Connection has read at least one message, as the step loop reads it.
     *
     * @return the messages, or null if the peer ended the stream
     * @throws IOException if a frame breaks the rules
     */
    List<Message> receive(Connection c) throws IOException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WAIT_MS);
        while (System.nanoTime() < deadline) {
            selector.select(50);
            selector.selectedKeys().clear();
            List<Message> got = c.read(readBuffer);
            if (got == null || !got.isEmpty()) {
                return got;
            }
        }
        throw new IllegalStateException("nothing arrived from " + c.peer() + " within " + WAIT_MS + " ms");
    }

    /** Writes every Connection's queue as its peer takes it, as the step loop does, until {@code done}. */
    void pumpUntil(BooleanSupplier done) throws IOException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WAIT_MS);
        while (!done.getAsBoolean()) {
            if (System.nanoTime() >= deadline) {
                throw new IllegalStateException("the peers did not take their frames within " + WAIT_MS + " ms");
            }
            selector.select(50);
            for (SelectionKey key : selector.selectedKeys()) {
                if (key.isValid() && key.isWritable()) {
                    ((Connection) key.attachment()).writable();
                }
            }
            selector.selectedKeys().clear();
        }
    }

    @Override
    public void close() throws IOException {
        for (Peer p : peers) {
            p.close();
            if (p.connection != null) {
                p.connection.shut();
            }
        }
        server.close();
        selector.close();
    }
}
