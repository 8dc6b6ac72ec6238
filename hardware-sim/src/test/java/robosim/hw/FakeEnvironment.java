package robosim.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.List;
import robosim.protocol.Command;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotRequests;
import robosim.protocol.RobotState;
import robosim.protocol.TimeStep;
import robosim.protocol.Welcome;

/**
 * An Environment played by a test: a listener on 127.0.0.1 that accepts one robot and speaks the
 * real frames with it. Every accept and read is bounded by {@link #WAIT_MS}.
 */
final class FakeEnvironment implements AutoCloseable {
    /** The longest any wait of a test lasts. */
    static final int WAIT_MS = 5_000;
    /** The step length the environment welcomes robots with, simulated ms. */
    static final int STEP_MS = 100;

    private final MessageCodec codec = new MessageCodec();
    private final ServerSocket listener;
    private Socket peer;
    private FrameReader in;
    private FrameWriter out;

    FakeEnvironment() throws IOException {
        listener = new ServerSocket(0, 1, loopback());
        listener.setSoTimeout(WAIT_MS);
    }

    static InetAddress loopback() throws IOException {
        return InetAddress.getByAddress(new byte[] {127, 0, 0, 1});
    }

    /**
     * A port on 127.0.0.1 that nothing listens on (it was free a moment ago).
     *
     * @return the port
     */
    static int closedPort() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 1, loopback())) {
            return s.getLocalPort();
        }
    }

    /** The state after {@code step}, at the origin, at time step · 100 ms. */
    static RobotState state(long step) {
        return new RobotState(step, step * STEP_MS, 0, 0, 0, 0, 0, 0, 0, false, 0);
    }

    /** @return the port robots connect to */
    int port() {
        return listener.getLocalPort();
    }

    /** Accepts a robot's connection and reads its first message, which must be a hello. */
    RobotHello acceptHello() throws IOException {
        peer = listener.accept();
        peer.setSoTimeout(WAIT_MS);
        in = new FrameReader(peer.getInputStream(), codec, FrameReader.DEFAULT_MAX_FRAME);
        out = new FrameWriter(peer.getOutputStream(), codec);
        return assertInstanceOf(RobotHello.class, in.read(), "the robot's first message");
    }

    /** Welcomes the robot with 100 ms steps and the state before step 1. */
    void welcome(String name) throws IOException {
        send(new Welcome(name, STEP_MS, state(0)));
    }

    void send(Message m) throws IOException {
        out.write(m);
    }

    /** @return the robot's next message, or null if it closed the connection */
    Message read() throws IOException {
        return in.read();
    }

    /**
     * Opens step {@code n} with the state after step n − 1 and reads the robot's answer.
     *
     * @return the requests the robot sent for step n
     */
    List<Command> step(long n) throws IOException {
        return step(n, state(n - 1));
    }

    /**
     * Opens step {@code n} with a state (whose time is the step's) and reads the robot's answer.
     *
     * @return the requests the robot sent for step n
     */
    List<Command> step(long n, RobotState after) throws IOException {
        send(new TimeStep(n, after.timeMs(), after));
        RobotRequests r = assertInstanceOf(RobotRequests.class, in.read(), "the robot's answer to step " + n);
        assertEquals(n, r.step(), "the step the robot's requests are for");
        return r.commands();
    }

    /** Asserts that the robot sends nothing for {@code ms}: a read that must time out. */
    void assertSilentFor(int ms) throws IOException {
        peer.setSoTimeout(ms);
        try {
            Message m = in.read();
            fail(m == null ? "the robot closed the connection" : "the robot sent " + m);
        } catch (SocketTimeoutException expected) {
            // nothing came
        } finally {
            peer.setSoTimeout(WAIT_MS);
        }
    }

    /** Closes the robot's connection, as an Environment that ends without a bye. */
    void closeConnection() throws IOException {
        if (peer != null) {
            peer.close();
        }
    }

    @Override
    public void close() throws IOException {
        try {
            closeConnection();
        } finally {
            listener.close();
        }
    }
}
