package robosim.cli;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.function.Predicate;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import robosim.protocol.Bye;
import robosim.protocol.ControlHello;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.RunSecret;

/**
 * A control client's connection to a running Environment's viewer port, shared by {@code robosim
 * comms} and {@code robosim control}: the run secret found as every client finds it, a
 * {@link ControlHello}, then messages both ways, each wait bounded.
 */
final class ControlConnection implements AutoCloseable {
    private final Socket socket;
    private final FrameWriter writer;
    private final FrameReader reader;

    private ControlConnection(Socket socket) throws IOException {
        this.socket = socket;
        MessageCodec codec = new MessageCodec();
        writer = new FrameWriter(socket.getOutputStream(), codec);
        reader = new FrameReader(socket.getInputStream(), codec, FrameReader.DEFAULT_MAX_FRAME);
    }

    /**
     * Finds the run secret (the option, then the places {@link RunSecret#find} looks).
     *
     * @return the secret, or null when there is none to present
     * @throws ParameterException if the secret given breaks its rule
     */
    static String token(CommandSpec spec, SecretOption secret, ViewerPortOptions at) {
        try {
            String bad = secret.apply();
            if (bad != null) {
                throw new IllegalArgumentException(bad);
            }
            return RunSecret.find(null, at.host, at.port());
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
    }

    /**
     * Connects and says hello.
     *
     * @param at        where the Environment's viewer port is
     * @param name      the client's name, for the Environment's log
     * @param token     the run secret, or null
     * @param timeoutMs the longest wait for connecting and for each answer
     * @return the connection, hello said
     * @throws IOException if the Environment cannot be reached
     */
    static ControlConnection open(ViewerPortOptions at, String name, String token, int timeoutMs) throws IOException {
        Socket s = new Socket();
        try {
            s.connect(new InetSocketAddress(at.host, at.port()), Math.min(timeoutMs, 10_000));
            s.setSoTimeout(timeoutMs);
            ControlConnection c = new ControlConnection(s);
            c.send(new ControlHello(name, token));
            return c;
        } catch (IOException | RuntimeException e) {
            s.close();
            throw e;
        }
    }

    /** Sends one message. */
    void send(Message m) throws IOException {
        writer.write(m);
    }

    /** The Environment said bye, or closed the connection, before the answer came. */
    static final class NoAnswerException extends IOException {
        private static final long serialVersionUID = 1L;

        NoAnswerException(String message) {
            super(message);
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
    <T extends Message> T answer(Class<T> type, Predicate<T> wanted) throws IOException {
        Message m;
        while ((m = reader.read()) != null) {
            if (type.isInstance(m) && wanted.test(type.cast(m))) {
                return type.cast(m);
            }
            if (m instanceof Bye bye) {
                throw new NoAnswerException("the Environment " + bye.reason());
            }
        }
        throw new NoAnswerException("the Environment closed the connection without an answer (its log says why)");
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}
