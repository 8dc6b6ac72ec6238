package robosim.hw;

import java.io.IOException;
import robosim.protocol.Message;

/**
 * What a {@link SharedLink} talks to the Environment through: a TCP connection
 * ({@link SocketLine}), or an Environment of this JVM directly ({@link InProcessLine}).
 */
interface MessageLine {
    /**
     * Waits for the Environment's next message.
     *
     * @return the message, or null once the Environment has closed the line
     * @throws java.net.SocketTimeoutException if nothing came for the link's lost time
     * @throws IOException                     if the line failed
     */
    Message read() throws IOException;

    /**
     * Sends a message; any thread may call it.
     *
     * @param message the message
     * @throws IOException if the line failed or is closed
     */
    void write(Message message) throws IOException;

    /** Closes the line; a thread waiting in {@link #read} returns. Closing twice does nothing. */
    void close();
}
