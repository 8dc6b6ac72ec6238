package robosim.panel.net;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import robosim.protocol.Bye;
import robosim.protocol.ControlHello;
import robosim.protocol.ControlReply;
import robosim.protocol.ControlRequest;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.LogLine;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.RunStatus;

/**
 * A viewer port on loopback that answers control clients as an Environment does: a status with
 * the step it has counted, every other request confirmed (a {@code log} followed by two log
 * lines); a {@code step} is held until
 * {@link #release} is counted down. Records the hellos' names and the requests.
 */
final class FakeEnvironment implements AutoCloseable {
    final ServerSocket server = new ServerSocket(0, 8, InetAddress.getLoopbackAddress());
    final List<String> hellos = new CopyOnWriteArrayList<>();
    final List<String> requests = new CopyOnWriteArrayList<>();
    final CountDownLatch release = new CountDownLatch(1);
    private final List<Socket> sockets = new CopyOnWriteArrayList<>();
    private final List<FrameWriter> writers = new CopyOnWriteArrayList<>();
    private final Thread acceptor;
    private final String secret;

    FakeEnvironment() throws IOException {
        this(null);
    }

    /** @param secret the run secret a hello must present, as the Environment asks it; null for none */
    FakeEnvironment(String secret) throws IOException {
        this.secret = secret;
        acceptor = new Thread(this::accept, "fake-environment");
        acceptor.setDaemon(true);
        acceptor.start();
    }

    int port() {
        return server.getLocalPort();
    }

    private void accept() {
        try {
            while (true) {
                Socket s = server.accept();
                sockets.add(s);
                Thread t = new Thread(() -> serve(s), "fake-environment-client");
                t.setDaemon(true);
                t.start();
            }
        } catch (IOException e) {
            // closed by the test
        }
    }

    private void serve(Socket s) {
        MessageCodec codec = new MessageCodec();
        try (s) {
            FrameReader in = new FrameReader(s.getInputStream(), codec, FrameReader.DEFAULT_MAX_FRAME);
            FrameWriter out = new FrameWriter(s.getOutputStream(), codec);
            writers.add(out);
            Message m;
            while ((m = in.read()) != null) {
                if (m instanceof ControlHello h) {
                    hellos.add(h.name());
                    if (secret != null && !secret.equals(h.token())) {
                        out.write(new Bye(Bye.REFUSED + "control client '" + h.name() + "' presented "
                                + (h.token() == null ? "no" : "a wrong") + " run secret"));
                        return;
                    }
                } else if (m instanceof ControlRequest r && r.op().equals("status")) {
                    out.write(new RunStatus(r.id(), "fake", requests.size(), 0, false, 0, List.of()));
                } else if (m instanceof ControlRequest r) {
                    requests.add(r.op());
                    if (r.op().equals("step")) {
                        release.await();
                    }
                    out.write(new ControlReply(r.id(), true, "did " + r.op()));
                    if (r.op().equals("log")) {
                        // as the Environment: the lines logged since come after the answer, between statuses
                        out.write(new LogLine(1, "INFO", "robot r1 connected"));
                        out.write(new LogLine(1, "WARNING", "closing robot r2: it disconnected"));
                    }
                }
            }
        } catch (IOException | InterruptedException e) {
            // the client went, or the test ended
        }
    }

    /**
     * Ends the run as the Environment does: a bye with the reason to every connection, then it stops
     * listening.
     */
    void end(String reason) throws IOException {
        for (FrameWriter w : writers) {
            try {
                w.write(new Bye(Bye.DONE + reason));
            } catch (IOException e) {
                // that client went already
            }
        }
        close();
    }

    @Override
    public void close() throws IOException {
        release.countDown();
        server.close();
        for (Socket s : sockets) {
            s.close();
        }
    }
}
