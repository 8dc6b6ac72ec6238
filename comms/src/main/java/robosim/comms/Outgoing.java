package robosim.comms;

/**
 * A message a robot sends: to one robot, to a group, or to everyone.
 *
 * @param id       the sender's number for it, so errors can name it
 * @param mode     how it is addressed
 * @param to       the recipient robot (point to point) or group (multicast); ignored for broadcast
 * @param kind     what the body is: {@code text}, or the name of the type a JSON body encodes
 * @param body     the payload
 */
public record Outgoing(long id, Mode mode, String to, String kind, String body) {
    /** How a message is addressed. */
    public enum Mode { POINT_TO_POINT, MULTICAST, BROADCAST }
}
