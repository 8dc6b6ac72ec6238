package robosim.viewer.net;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.atomic.AtomicReference;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;

/**
 * An Environment's viewer port in a thread, on 127.0.0.1 and a free port: it accepts one viewer,
 * reads its hello, plays a script, and then holds the connection until the viewer hangs up. Every wait
 * has a timeout so a broken client cannot hang the test run.
 */
final class FakeEnvironment implements AutoCloseable {
    /** What the environment says once the viewer has said hello. */
    @FunctionalInterface
    interface Script {
        void play(FrameWriter out, Socket socket) throws IOException;
    }

    private static final int WAIT_MS = 10_000;

    private final ServerSocket server;
    private final Thread thread;
    private final AtomicReference<Message> hello = new AtomicReference<>();
    private final AtomicReference<Throwable> failure = new AtomicReference<>();

    FakeEnvironment(Script script) throws IOException {
        server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        server.setSoTimeout(WAIT_MS);
        thread = new Thread(() -> serve(script), "fake-environment");
        thread.setDaemon(true);
        thread.start();
    }

    private void serve(Script script) {
        MessageCodec codec = new MessageCodec();
        try (Socket socket = server.accept()) {
            socket.setSoTimeout(WAIT_MS);
            FrameReader in = new FrameReader(socket.getInputStream(), codec, FrameReader.DEFAULT_MAX_FRAME);
            hello.set(in.read());
            script.play(new FrameWriter(socket.getOutputStream(), codec), socket);
            // Hold the connection until the viewer hangs up, as the real Environment would.
            while (socket.getInputStream().read() >= 0) {
                continue;
            }
        } catch (IOException | RuntimeException e) {
            failure.set(e);
        }
    }

    int port() {
        return server.getLocalPort();
    }

    /** @return the first message the viewer sent, or {@code null} if none came */
    Message hello() throws InterruptedException {
        thread.join(WAIT_MS);
        return hello.get();
    }

    /** @return what went wrong on the server side, if anything */
    Throwable failure() {
        return failure.get();
    }

    @Override
    public void close() throws IOException {
        server.close();
        try {
            thread.join(WAIT_MS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
