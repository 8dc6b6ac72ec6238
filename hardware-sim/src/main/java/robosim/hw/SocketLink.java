package robosim.hw;

import java.io.IOException;
import java.net.SocketTimeoutException;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.protocol.Bye;
import robosim.protocol.Command;
import robosim.protocol.KeepAlive;
import robosim.protocol.Message;
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

    private final RobotRuntime runtime;
    private final String host;
    private final int port;
    private final HardwareOptions options;
    private volatile SocketLine line;

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
            // the welcome may take the connect timeout; once in the run, silence is bounded by the lost time
            line = SocketLine.connect(host, port, options, options.connectTimeoutMs());
            line.write(secret == null ? hello : hello.withToken(secret.get()));
            Message first = line.read();
            while (first instanceof KeepAlive) {
                first = line.read();
            }
            if (!(first instanceof Welcome w)) {
                throw refusal(host, port, first);
            }
            line.readTimeout(options.lostAfterMs());
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
            while ((m = line.read()) != null) {
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
        line.write(new RobotRequests(step, commands(requests)));
    }

    @Override
    public void bye(String reason) {
        try {
            line.write(new Bye(reason));
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
        SocketLine l = line;
        if (l != null) {
            l.close();
        }
    }
}
