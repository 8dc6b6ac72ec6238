package robosim.panel.net;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.Predicate;
import java.util.function.Supplier;
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
 * A control client's connection to a running Environment's viewer port: a {@link ControlHello}
 * with the run secret, then requests and their answers, each wait bounded by the socket's timeout.
 * Used by {@code robosim control}, {@code robosim comms} and the ControlPanel. Not thread-safe: one
 * thread asks at a time.
 */
public final class ControlClient implements AutoCloseable {
    private volatile Consumer<LogLine> logLines;
    private final Socket socket;
    private final FrameWriter writer;
    private final FrameReader reader;
    private long nextId = 1;

    private ControlClient(Socket socket) throws IOException {
        this.socket = socket;
        MessageCodec codec = new MessageCodec();
        writer = new FrameWriter(socket.getOutputStream(), codec);
        reader = new FrameReader(socket.getInputStream(), codec, FrameReader.DEFAULT_MAX_FRAME);
    }

    /**
     * Connects and says hello.
     *
     * @param host      the Environment's host
     * @param port      its viewer port
     * @param name      the client's name, for the Environment's log
     * @param token     the run secret, or null
     * @param timeoutMs the longest wait for connecting (at most 10 s) and for each answer
     * @return the connection, hello said
     * @throws IOException if the Environment cannot be reached
     */
    public static ControlClient open(String host, int port, String name, String token, int timeoutMs)
            throws IOException {
        return open(host, port, name, () -> token, timeoutMs);
    }

    /**
     * Connects and says hello, presenting the secret {@code token} gives once the connection is open:
     * an Environment writes its secret before it listens, so a secret looked up then is this run's.
     *
     * @param host      the Environment's host
     * @param port      its viewer port
     * @param name      the client's name, for the Environment's log
     * @param token     gives the run secret, or null for none
     * @param timeoutMs the longest wait for connecting (at most 10 s) and for each answer
     * @return the connection, hello said
     * @throws IOException if the Environment cannot be reached
     */
    public static ControlClient open(String host, int port, String name, Supplier<String> token, int timeoutMs)
            throws IOException {
        Socket s = new Socket();
        try {
            s.connect(new InetSocketAddress(host, port), Math.min(timeoutMs, 10_000));
            s.setSoTimeout(timeoutMs);
            ControlClient c = new ControlClient(s);
            c.send(new ControlHello(name, token.get()));
            return c;
        } catch (IOException | RuntimeException e) {
            s.close();
            throw e;
        }
    }

    /**
     * Sends one message.
     *
     * @param m the message
     * @throws IOException if writing fails
     */
    public void send(Message m) throws IOException {
        writer.write(m);
    }

    /** The Environment said bye, or closed the connection, before the answer came. */
    public static final class NoAnswerException extends IOException {
        private static final long serialVersionUID = 1L;
        private final String byeReason;

        /** @param message why no answer came */
        public NoAnswerException(String message) {
            this(message, null);
        }

        /**
         * @param message   why no answer came
         * @param byeReason the reason of the Environment's bye, or null when it closed without one
         */
        public NoAnswerException(String message, String byeReason) {
            super(message);
            this.byeReason = byeReason;
        }

        /** @return the reason of the Environment's bye (such as {@code refused: ...}), or null if none came */
        public String byeReason() {
            return byeReason;
        }
    }

    /**
     * Reads until the answer wanted comes, skipping other messages.
     *
     * @param type   the answer's type
     * @param wanted which message of that type is the answer
     * @param <T>    the answer's type
     * @return the answer
     * @throws NoAnswerException saying why, when a bye or the connection's end comes first
     * @throws IOException       if reading fails or times out
     */
    public <T extends Message> T answer(Class<T> type, Predicate<T> wanted) throws IOException {
        Message m;
        while ((m = reader.read()) != null) {
            if (type.isInstance(m) && wanted.test(type.cast(m))) {
                return type.cast(m);
            }
            if (m instanceof LogLine line && logLines != null) {
                logLines.accept(line);
                continue;
            }
            if (m instanceof Bye bye) {
                throw new NoAnswerException("the Environment " + bye.reason(), bye.reason());
            }
        }
        throw new NoAnswerException("the Environment closed the connection without an answer (its log says why)");
    }

    /**
     * Has the Environment's log lines, once asked for with a {@code log} request, handed over while
     * this client reads its answers.
     *
     * @param lines gets each line, on the reading thread; null for none
     */
    public void onLogLine(Consumer<LogLine> lines) {
        this.logLines = lines;
    }

    /**
     * Sends a request and waits for its reply.
     *
     * @param op   the operation
     * @param args its arguments, as a user types them
     * @return the Environment's reply: what it did, or why it refused
     * @throws IOException if no answer comes (see {@link #answer})
     */
    public ControlReply ask(String op, String... args) throws IOException {
        long id = nextId++;
        send(new ControlRequest(id, op, List.of(args)));
        return answer(ControlReply.class, r -> r.id() == id);
    }

    /**
     * Asks for the run's status.
     *
     * @return the status
     * @throws IOException if no status comes, or the Environment refused (one that does not know
     *                     {@code status} answers with a refusal, reported here with its reason)
     */
    public RunStatus status() throws IOException {
        long id = nextId++;
        send(new ControlRequest(id, "status", List.of()));
        Message m = answer(Message.class, x -> x instanceof RunStatus s && s.id() == id
                || x instanceof ControlReply r && r.id() == id);
        if (m instanceof ControlReply refused) {
            throw new IOException("the Environment did not give its status: " + refused.text());
        }
        return (RunStatus) m;
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}
