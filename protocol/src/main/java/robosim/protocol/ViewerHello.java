package robosim.protocol;

/**
 * The first message of a viewer's connection.
 *
 * @param name a name for the viewer, for the Environment's log
 */
public record ViewerHello(String name) implements Message {
}
