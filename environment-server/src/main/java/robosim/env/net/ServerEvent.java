package robosim.env.net;

import robosim.protocol.Message;

/** What the connections tell the session rules, as the step loop reads them. */
sealed interface ServerEvent {
    /** A peer sent a message. */
    record Received(Connection from, Message message) implements ServerEvent { }

    /** A peer's connection ended. */
    record Closed(Connection from, String reason) implements ServerEvent { }
}
