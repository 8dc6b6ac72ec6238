package robosim.comms;

/**
 * A message as it reaches a robot.
 *
 * @param from     the sender
 * @param mode     how it was addressed
 * @param to       the robot or group it was addressed to ({@code *} for broadcast)
 * @param kind     what the body is
 * @param body     the payload
 * @param sentStep the step in which it was sent
 * @param id       the sender's number for it
 */
public record Delivery(String from, Outgoing.Mode mode, String to, String kind, String body, long sentStep, long id) {
}
