package robosim.protocol;

/**
 * A message as it reaches a robot.
 *
 * @param from     the sender
 * @param mode     how it was addressed
 * @param to       the robot or group it was addressed to ({@code *} for everyone)
 * @param kind     {@code text}, or the name of the type the JSON body encodes
 * @param body     the payload
 * @param sentStep the step in which it was sent
 * @param id       the sender's number for it
 */
public record MessageDelivery(String from, Command.Addressing mode, String to, String kind, String body,
                              long sentStep, long id) {
}
