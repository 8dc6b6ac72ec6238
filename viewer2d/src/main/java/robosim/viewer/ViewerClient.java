package robosim.viewer;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.protocol.Bye;
import robosim.protocol.FrameException;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.ViewerFrame;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldDescription;

/**
 * The viewer side of the wire: attaches to an Environment's viewer port, says
 * {@link ViewerHello}, takes the {@link WorldDescription} that must come first, then draws the
 * {@link ViewerFrame}s that follow until a {@link Bye} or the end of the stream.
 *
 * <p>Frames whose step is a multiple of {@link ViewerOptions#every()} are rendered with a
 * {@link WorldRenderer} and handed to a {@link FrameSink}; so is the last frame received, so that
 * the final state is always kept. A later {@code WorldDescription} (a world reloaded by a control
 * panel) replaces the world for the frames after it.
 *
 * <p>No wait is unbounded: the connection has {@link ViewerOptions#connectTimeout()} and each
 * message {@link ViewerOptions#readTimeout()}. Every failure ends {@link #run()} with a
 * {@link ViewerException} that names the Environment and the reason.
 */
public final class ViewerClient {
    private static final Logger LOG = Logger.getLogger(ViewerClient.class.getName());

    private final ViewerOptions options;
    private final FrameSink sink;
    private final WorldRenderer renderer;
    private final MessageCodec codec = new MessageCodec();

    /**
     * @param options where to attach and what to draw
     * @param sink    where the rendered frames go, such as a {@link PngFrameWriter}
     */
    public ViewerClient(ViewerOptions options, FrameSink sink) {
        this(options, sink, new WorldRenderer());
    }

    /**
     * @param options  where to attach and what to draw
     * @param sink     where the rendered frames go
     * @param renderer draws the frames
     */
    public ViewerClient(ViewerOptions options, FrameSink sink, WorldRenderer renderer) {
        if (options == null || sink == null || renderer == null) {
            throw new IllegalArgumentException("null was supplied for "
                    + (options == null ? "options" : sink == null ? "sink" : "renderer") + ": it is required");
        }
        this.options = options;
        this.sink = sink;
        this.renderer = renderer;
    }

    /** @return the options this client runs with */
    public ViewerOptions options() {
        return options;
    }

    /**
     * Attaches, draws until the Environment says goodbye or closes the stream, and detaches.
     *
     * @return what was received and written
     * @throws ViewerException if the Environment cannot be reached, is silent for longer than the
     *                         read timeout, breaks the protocol, or the sink fails
     */
    public ViewerSummary run() throws ViewerException {
        Socket socket = connect();
        try {
            socket.setSoTimeout(Math.toIntExact(options.readTimeout().toMillis()));
            new FrameWriter(socket.getOutputStream(), codec).write(new ViewerHello(options.name()));
            return new Session(new FrameReader(socket.getInputStream(), codec, options.maxFrame())).run();
        } catch (ViewerException e) {
            throw e;
        } catch (IOException e) {
            throw new ViewerException("cannot greet the environment at " + options.peer() + ": "
                    + e.getClass().getSimpleName() + ": " + e.getMessage(), e);
        } finally {
            closeQuietly(socket);
        }
    }

    private Socket connect() throws ViewerException {
        int timeoutMs = Math.toIntExact(options.connectTimeout().toMillis());
        Socket socket = new Socket();
        try {
            socket.connect(new InetSocketAddress(options.host(), options.port()), timeoutMs);
            LOG.info(() -> "viewer '" + options.name() + "' connected to the environment at " + options.peer());
            return socket;
        } catch (IOException e) {
            closeQuietly(socket);
            String why = e instanceof SocketTimeoutException ? "no answer within " + timeoutMs + " ms (connectTimeout)"
                    : e.getClass().getSimpleName() + ": " + e.getMessage();
            throw new ViewerException("cannot connect to the environment at " + options.peer() + ": " + why, e);
        }
    }

    private static void closeQuietly(Socket socket) {
        try {
            socket.close();
        } catch (IOException e) {
            LOG.log(Level.FINE, "closing a viewer socket failed", e);
        }
    }

    /** One attachment's reading loop and counters. */
    private final class Session {
        private final FrameReader in;
        private WorldDescription world;
        private long received;
        private long written;
        private long lastStep = -1;
        private ViewerFrame last;
        private boolean lastWritten;

        Session(FrameReader in) {
            this.in = in;
        }

        ViewerSummary run() throws ViewerException {
            Message first = read("the world description");
            if (first == null) {
                throw fail("closed the connection before sending the world description", null);
            }
            if (!(first instanceof WorldDescription description)) {
                throw fail("broke the protocol: the first message must be a world description, not "
                        + first.getClass().getSimpleName(), null);
            }
            accept(description);
            while (true) {
                Message m = read("a frame");
                if (m == null || m instanceof Bye) {
                    String reason = m == null ? "end of stream" : ((Bye) m).reason();
                    if (last != null && !lastWritten) {
                        write(last);
                    }
                    ViewerSummary summary = new ViewerSummary(world.name(), received, written, lastStep, reason);
                    LOG.info(() -> "viewer '" + options.name() + "' detached from " + options.peer() + ": " + summary);
                    return summary;
                } else if (m instanceof ViewerFrame frame) {
                    received++;
                    lastStep = frame.step();
                    last = frame;
                    lastWritten = false;
                    if (frame.step() % options.every() == 0) {
                        write(frame);
                    }
                } else if (m instanceof WorldDescription reloaded) {
                    // The old world's last frame is drawn with the old world before it is replaced.
                    if (last != null && !lastWritten) {
                        write(last);
                    }
                    last = null;
                    accept(reloaded);
                } else {
                    throw fail("broke the protocol after step " + lastStep + ": a viewer expects frames, not "
                            + m.getClass().getSimpleName(), null);
                }
            }
        }

        private void accept(WorldDescription description) throws ViewerException {
            try {
                ViewTransform.fit(description, options.render().width());
            } catch (IllegalArgumentException e) {
                throw fail("sent a world that cannot be drawn: " + e.getMessage(), e);
            }
            world = description;
            LOG.info(() -> "world '" + description.name() + "' from " + options.peer() + ": " + description.width()
                    + " x " + description.height() + " mm, " + description.obstacles().size() + " obstacles, "
                    + description.robots().size() + " robots");
        }

        private void write(ViewerFrame frame) throws ViewerException {
            BufferedImage image = renderer.render(world, frame, options.render());
            try {
                sink.accept(frame.step(), image);
            } catch (IOException e) {
                throw new ViewerException("cannot store the frame of step " + frame.step() + " from "
                        + options.peer() + ": " + e.getMessage(), e);
            }
            written++;
            lastWritten = true;
            LOG.fine(() -> "wrote the frame of step " + frame.step());
        }

        private Message read(String expected) throws ViewerException {
            try {
                return in.read();
            } catch (SocketTimeoutException e) {
                throw fail("sent nothing for " + options.readTimeout().toMillis() + " ms (readTimeout) while "
                        + "the viewer waited for " + expected + after(), e);
            } catch (FrameException e) {
                throw fail("broke the protocol" + after() + ": " + e.getMessage(), e);
            } catch (IOException e) {
                throw fail("dropped the connection" + after() + ": " + e.getClass().getSimpleName() + ": "
                        + e.getMessage(), e);
            }
        }

        private String after() {
            return lastStep < 0 ? "" : " after step " + lastStep;
        }

        private ViewerException fail(String what, Throwable cause) {
            return new ViewerException("the environment at " + options.peer() + " " + what, cause);
        }
    }
}
