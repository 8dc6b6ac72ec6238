package robosim.env.net;

import robosim.protocol.Message;

/** What the connections tell the step loop; the loop is the only thread that changes state. */
sealed interface ServerEvent {
    /** A peer sent a message. */
    record Received(Connection from, Message message) implements ServerEvent { }

    /** A peer's connection ended. */
    record Closed(Connection from, String reason) implements ServerEvent { }

    /** A peer connected. */
    record Accepted(Connection from) implements ServerEvent { }
}
