package robosim.protocol;

/**
 * The last message of a connection, from either side.
 *
 * @param reason why the connection ends; {@code "done"} for an orderly end
 */
public record Bye(String reason) implements Message {
}
