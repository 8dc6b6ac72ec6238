package robosim.hw;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.protocol.Bye;
import robosim.protocol.Command;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotRequests;
import robosim.protocol.TimeStep;
import robosim.protocol.Welcome;

/**
 * A robot's link to the Environment, one thread per robot. Each step its thread receives the time
 * step and the responses and hands them to the Robot-Object through the {@link StepGate}; once the
 * robot's code has yielded, the {@code robotRequestQueue} is drained and sent as the robot's
 * requests for the step (by the last robot thread to yield, so no thread wakes just to send). One
 * watchdog thread per JVM sends for robots whose code ended without yielding, and warns about code
 * that does not yield.
 */
public final class HardwareSimulator {
    private static final Logger LOG = Logger.getLogger(HardwareSimulator.class.getName());
    private static final long RETRY_MS = 200;
    private static final long WATCH_MS = 50;
    private static final List<HardwareSimulator> WATCHED = new CopyOnWriteArrayList<>();

    static {
        Thread watchdog = new Thread(() -> {
            while (true) {
                for (HardwareSimulator hw : WATCHED) {
                    hw.watch();
                }
                try {
                    Thread.sleep(WATCH_MS);
                } catch (InterruptedException e) {
                    return;
                }
            }
        }, "hw-watchdog");
        watchdog.setDaemon(true);
        watchdog.start();
    }

    private final RobotHello hello;
    private final StepGate gate;
    private final Consumer<RobotSensorResponse> responses;
    private final Queue<RobotRequest> robotRequestQueue = new ConcurrentLinkedQueue<>();
    /** One codec for every robot of the JVM: Jackson's mapper is thread-safe, and costly to warm. */
    private static final MessageCodec CODEC = new MessageCodec();
    private final HardwareOptions options;
    private Socket socket;
    private FrameWriter writer;
    private FrameReader reader;
    private volatile String endReason;
    private volatile long openStep;
    private volatile Thread keeper;
    private long warnedStep = -1;

    /**
     * @param hello     the robot's name, type and parameters
     * @param gate      where the robot's code yields
     * @param responses receives each step's response, inside the gate's lock
     * @param options   timeouts
     */
    public HardwareSimulator(RobotHello hello, StepGate gate, Consumer<RobotSensorResponse> responses,
                             HardwareOptions options) {
        this.hello = hello;
        this.gate = gate;
        this.responses = responses;
        this.options = options;
        gate.onAllYielded(this::sendRequests);
    }

    /**
     * Connects, says hello and waits (bounded) for the Environment's welcome.
     *
     * @param host the Environment's host
     * @param port its robot port
     * @return the welcome, with the robot's state before the first step
     * @throws IOException if the connection fails or the Environment refuses the robot
     */
    public Welcome connect(String host, int port) throws IOException {
        long deadline = System.currentTimeMillis() + options.connectTimeoutMs();
        while (true) {
            socket = new Socket();
            try {
                socket.connect(new InetSocketAddress(host, port), (int) options.connectTimeoutMs());
                break;
            } catch (ConnectException e) {
                // the Environment may still be starting: try again until the connect timeout
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
        try {
            socket.setTcpNoDelay(true);
            socket.setSoTimeout((int) options.connectTimeoutMs());
            reader = new FrameReader(socket.getInputStream(), CODEC, FrameReader.DEFAULT_MAX_FRAME);
            writer = new FrameWriter(socket.getOutputStream(), CODEC);
            writer.write(hello);
            Message first = reader.read();
            if (first instanceof Welcome w) {
                socket.setSoTimeout((int) options.stepReadTimeoutMs());
                return w;
            }
            throw new IOException(first instanceof Bye bye ? "the Environment at " + host + ":" + port + " "
                    + bye.reason() : "the Environment at " + host + ":" + port + " answered " + describe(first));
        } catch (IOException e) {
            socket.close();
            throw e;
        }
    }

    /** Starts the robot's hardware thread; call after {@link #connect}. */
    public void start() {
        WATCHED.add(this);
        RobotThreads.unstarted("hw-" + hello.name(), this::run).start();
    }

    /** @param request a request of the robot's code, sent with the current step's requests */
    public void request(RobotRequest request) {
        robotRequestQueue.add(request);
    }

    /**
     * Keeps the robot connected, and the JVM up, after every thread of its code has ended, until
     * the connection ends.
     *
     * @param keep whether to keep it
     */
    public synchronized void keepAlive(boolean keep) {
        if (keep && keeper == null) {
            Thread t = new Thread(() -> {
                try {
                    gate.awaitClosed();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, "hw-keep-" + hello.name());
            keeper = t;
            t.start();
        } else if (!keep && keeper != null) {
            keeper.interrupt();
            keeper = null;
        }
    }

    /** @return why the connection ended, or null while connected */
    public String endReason() {
        return endReason;
    }

    /**
     * Leaves the run: says bye and closes.
     *
     * @param reason for the Environment's log
     */
    public void disconnect(String reason) {
        try {
            writer.write(new Bye(reason));
        } catch (IOException e) {
            LOG.log(Level.FINE, "bye not sent", e);
        }
        end("disconnected: " + reason);
    }

    private void run() {
        String reason = "the Environment closed the connection";
        try {
            Message m;
            while ((m = reader.read()) != null) {
                if (m instanceof TimeStep ts) {
                    openStep = ts.step();
                    RobotSensorResponse r = new RobotSensorResponse(ts.state());
                    if (gate.advance(r.step(), r.timeMs(), () -> responses.accept(r))) {
                        sendRequests();
                    }
                } else if (m instanceof Bye bye) {
                    reason = "the Environment said " + bye.reason();
                    break;
                } else {
                    reason = "the Environment sent " + describe(m);
                    break;
                }
            }
        } catch (SocketTimeoutException e) {
            reason = "no step arrived within " + options.stepReadTimeoutMs() + " ms";
        } catch (IOException e) {
            reason = endReason != null ? endReason : e.getMessage();
        }
        end(reason);
    }

    /**
     * Sends the open step's requests: everything the robot's code queued before it yielded. Run by
     * whichever thread saw the robot's code yield (see {@link StepGate}); if the code has ended,
     * says bye instead.
     */
    private void sendRequests() {
        try {
            if (gate.participantCount() == 0 && keeper == null) {
                writer.write(new Bye("the robot's code has ended"));
                end("the robot's code has ended");
                return;
            }
            List<Command> commands = new ArrayList<>();
            RobotRequest req;
            while ((req = robotRequestQueue.poll()) != null) {
                commands.add(req.command());
            }
            writer.write(new RobotRequests(openStep, commands));
        } catch (IOException e) {
            end("sending requests failed: " + e.getMessage());
        }
    }

    /** Looks after robots whose code ended without yielding, and warns about code that never yields. */
    private void watch() {
        if (gate.claimIfYielded()) {
            sendRequests();
            return;
        }
        long unsent = gate.unsentNanos();
        long warnAfter = options.yieldWarningMs() * 1_000_000L;
        if (unsent > warnAfter && warnedStep != openStep) {
            warnedStep = openStep;
            LOG.warning(() -> "robot " + hello.name() + "'s code has not yielded for step " + openStep + " after "
                    + options.yieldWarningMs() + " ms; it should wait with ArUtil.sleep or a blocking call");
        }
    }

    private void end(String reason) {
        WATCHED.remove(this);
        if (endReason == null) {
            endReason = reason;
            LOG.fine(() -> "robot " + hello.name() + ": " + reason);
        }
        gate.close();
        try {
            socket.close();
        } catch (IOException e) {
            LOG.log(Level.FINE, "closing", e);
        }
    }

    private static String describe(Message m) {
        return m == null ? "nothing (the connection closed)" : "an unexpected " + m.getClass().getSimpleName();
    }
}
