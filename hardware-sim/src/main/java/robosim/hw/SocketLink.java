package robosim.hw;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.protocol.Bye;
import robosim.protocol.Command;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.KeepAlive;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotRequests;
import robosim.protocol.TimeStep;
import robosim.protocol.Welcome;

/**
 * A robot's connection of its own: its hello, then a {@link TimeStep} in and a
 * {@link RobotRequests} out each step, read by a thread of the robot's own. A {@link KeepAlive}
 * counts only as a sign of life: the read gives up after {@link HardwareOptions#lostAfterMs()}
 * without a byte.
 */
final class SocketLink extends ReleasedOnClose {
    private static final Logger LOG = Logger.getLogger(SocketLink.class.getName());
    private static final long RETRY_MS = 200;
    /** One codec for every link of the JVM: Jackson's mapper is thread-safe, and costly to warm. */
    static final MessageCodec CODEC = new MessageCodec();

    private final RobotRuntime runtime;
    private final String host;
    private final int port;
    private final HardwareOptions options;
    private Socket socket;
    private FrameWriter writer;
    private FrameReader reader;

    /**
     * @param runtime  the runtime whose choices make the link's thread
     * @param host     the Environment's host
     * @param port     its robot port
     * @param options  timeouts
     * @param released run once when the link closes
     */
    SocketLink(RobotRuntime runtime, String host, int port, HardwareOptions options, Runnable released) {
        super(released);
        this.runtime = runtime;
        this.host = host;
        this.port = port;
        this.options = options;
    }

    /**
     * Connects, trying again while nothing listens (the Environment may still be starting) until
     * the connect timeout.
     */
    static Socket connectSocket(String host, int port, HardwareOptions options) throws IOException {
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

    /** @return the Environment's refusal or odd answer to a hello, as a connect failure */
    static IOException refusal(String host, int port, Message answer) {
        String at = "the Environment at " + host + ":" + port;
        return answer instanceof Bye bye ? new RefusedException(at + " " + bye.reason(), RunEnd.withoutPrefix(bye.reason()))
                : new IOException(at + " answered " + describe(answer));
    }

    static String describe(Message m) {
        return m == null ? "nothing (the connection closed)" : "an unexpected " + m.getClass().getSimpleName();
    }

    /** The reason a link gives when the Environment closes the connection without a bye. */
    static final String CLOSED = "it closed the connection without a bye";

    /** @return the reason a link gives when the Environment has been silent for the lost time */
    static String silent(HardwareOptions options) {
        return "it sent nothing, neither a step nor a keep-alive, for " + options.lostAfterMs() + " ms";
    }

    static List<Command> commands(List<RobotRequest> requests) {
        List<Command> commands = new ArrayList<>(requests.size());
        for (RobotRequest r : requests) {
            commands.add(r.command());
        }
        return commands;
    }

    @Override
    public Welcome open(RobotHello hello, StepReceiver receiver) throws IOException {
        return open(hello, null, receiver);
    }

    @Override
    public Welcome open(RobotHello hello, Supplier<String> secret, StepReceiver receiver) throws IOException {
        try {
            socket = connectSocket(host, port, options);
            socket.setSoTimeout((int) options.connectTimeoutMs());
            reader = new FrameReader(socket.getInputStream(), CODEC, FrameReader.DEFAULT_MAX_FRAME);
            writer = new FrameWriter(socket.getOutputStream(), CODEC);
            writer.write(secret == null ? hello : hello.withToken(secret.get()));
            Message first = reader.read();
            while (first instanceof KeepAlive) {
                first = reader.read();
            }
            if (!(first instanceof Welcome w)) {
                throw refusal(host, port, first);
            }
            socket.setSoTimeout((int) options.lostAfterMs());
            runtime.readerThread("hw-" + hello.name(), () -> read(receiver)).start();
            return w;
        } catch (IOException | RuntimeException e) {
            close();
            throw e;
        }
    }

    private void read(StepReceiver receiver) {
        RunEnd.Kind kind = RunEnd.Kind.LOST;
        String reason = CLOSED;
        try {
            Message m;
            while ((m = reader.read()) != null) {
                if (m instanceof TimeStep ts) {
                    receiver.step(new RobotSensorResponse(ts.step(), ts.state()));
                } else if (m instanceof KeepAlive) {
                    continue; // a sign of life: the read's timeout starts again
                } else if (m instanceof Bye bye) {
                    kind = RunEnd.ofBye(bye.reason());
                    reason = RunEnd.withoutPrefix(bye.reason());
                    break;
                } else {
                    reason = "it sent " + describe(m);
                    break;
                }
            }
        } catch (SocketTimeoutException e) {
            reason = silent(options);
        } catch (IOException e) {
            reason = "the connection failed: " + e.getMessage();
        }
        receiver.ended(kind, reason);
        close();
    }

    @Override
    public void send(long step, List<RobotRequest> requests) throws IOException {
        writer.write(new RobotRequests(step, commands(requests)));
    }

    @Override
    public void bye(String reason) {
        try {
            writer.write(new Bye(reason));
        } catch (IOException | RuntimeException e) {
            LOG.log(Level.FINE, "bye not sent", e);
        }
        close();
    }

    @Override
    public String environment() {
        return host + ":" + port;
    }

    @Override
    void closed() {
        if (socket != null) {
            try {
                socket.close();
            } catch (IOException e) {
                LOG.log(Level.FINE, "closing", e);
            }
        }
    }
}
