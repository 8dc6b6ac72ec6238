package robosim.viewer.net;

import java.time.Duration;
import robosim.protocol.FrameReader;

/**
 * How a {@link ViewerClient} attaches. Start from {@link #of(String, int)} and
 * change what differs with the {@code with...} methods.
 *
 * @param host           the Environment's host
 * @param port           its viewer port, 1 to 65535
 * @param name           the name the viewer gives in its {@code ViewerHello}
 * @param connectTimeout the longest wait for the connection, positive; while nothing listens (an
 *                       Environment starting) the client tries again within it
 * @param readTimeout    the longest wait for any one message, positive
 * @param maxFrame       the largest frame payload accepted, in bytes
 */
public record ViewerOptions(String host, int port, String name, 
                            Duration connectTimeout, Duration readTimeout, int maxFrame) {
    /** The default connect timeout, 10 s. */
    public static final Duration DEFAULT_CONNECT_TIMEOUT = Duration.ofSeconds(10);
    /** The default read timeout, 60 s: longer than any sane step deadline. */
    public static final Duration DEFAULT_READ_TIMEOUT = Duration.ofSeconds(60);

    /**
     * Checks every option and names the one that is wrong.
     *
     * @param host           the Environment's host
     * @param port           its viewer port, 1 to 65535
     * @param name           the viewer's name
     * @param connectTimeout the longest wait for the connection, from 1 ms
     * @param readTimeout    the longest wait for any one message, from 1 ms
     * @param maxFrame       the largest frame payload accepted, at least 1 byte
     * @throws IllegalArgumentException if an option is missing or out of range
     */
    public ViewerOptions {
        if (host == null || host.isBlank()) {
            throw new IllegalArgumentException("'" + host + "' was supplied for host: host must not be blank");
        }
        if (port < 1 || port > 65535) {
            throw new IllegalArgumentException(port + " was supplied for port: port must be from 1 to 65535");
        }
        if (name == null) {
            throw new IllegalArgumentException("null was supplied for name: name is required");
        }
        positiveMillis("connectTimeout", connectTimeout);
        positiveMillis("readTimeout", readTimeout);
        if (maxFrame < 1) {
            throw new IllegalArgumentException(maxFrame + " was supplied for maxFrame: maxFrame must be at least 1");
        }
    }

    private static void positiveMillis(String option, Duration value) {
        if (value == null || value.toMillis() < 1 || value.toMillis() > Integer.MAX_VALUE) {
            throw new IllegalArgumentException(value + " was supplied for " + option + ": " + option
                    + " must be from 1 ms to " + Integer.MAX_VALUE + " ms");
        }
    }

    /**
     * The defaults: name {@code "viewer2d"}, the default
     * timeouts and {@link FrameReader#DEFAULT_MAX_FRAME}.
     *
     * @param host the Environment's host
     * @param port its viewer port
     * @return the options
     */
    public static ViewerOptions of(String host, int port) {
        return new ViewerOptions(host, port, "viewer2d",
                DEFAULT_CONNECT_TIMEOUT, DEFAULT_READ_TIMEOUT, FrameReader.DEFAULT_MAX_FRAME);
    }

    /**
     * @param newName the viewer's name
     * @return these options with that name
     */
    public ViewerOptions withName(String newName) {
        return new ViewerOptions(host, port, newName, connectTimeout, readTimeout, maxFrame);
    }

    /**
     * @param newTimeout the connect timeout
     * @return these options with it
     */
    public ViewerOptions withConnectTimeout(Duration newTimeout) {
        return new ViewerOptions(host, port, name, newTimeout, readTimeout, maxFrame);
    }

    /**
     * @param newTimeout the read timeout
     * @return these options with it
     */
    public ViewerOptions withReadTimeout(Duration newTimeout) {
        return new ViewerOptions(host, port, name, connectTimeout, newTimeout, maxFrame);
    }

    /** @return {@code host:port}, for messages */
    public String peer() {
        return host + ":" + port;
    }
}
