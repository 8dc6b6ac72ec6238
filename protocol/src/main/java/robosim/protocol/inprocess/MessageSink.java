package robosim.protocol.inprocess;

import robosim.protocol.Message;

/**
 * One direction of an in-process link: where the messages of one side go, as objects, never
 * encoded. The Environment's side and the robots' side each hand the other a sink when the link
 * opens. A message handed over is shared, not copied: neither side changes it afterwards (the
 * wire's messages are immutable records; the arrays a state part carries are copies the
 * Environment made for that state alone).
 */
public interface MessageSink {
    /**
     * Hands over a message; returns at once, whatever the other side is doing.
     *
     * @param message the message
     */
    void deliver(Message message);

    /**
     * The sending side has closed the link: nothing more comes. Called at most once.
     *
     * @param reason why, for the other side's log
     */
    void closed(String reason);
}
