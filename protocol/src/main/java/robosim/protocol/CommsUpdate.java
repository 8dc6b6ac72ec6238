package robosim.protocol;

/**
 * Changes how messages travel while a run goes on; sent by a control peer on the viewer port after
 * its {@link ViewerHello}. A null field keeps its current value. The Environment confirms with a
 * {@code CommsUpdate} holding every setting now in force, or closes the peer if a setting breaks
 * a rule.
 *
 * @param maxRange        the farthest a message reaches, mm (0: no limit)
 * @param wallsBlock      whether walls stop messages
 * @param latencySteps    steps between sending and delivery, at least 1
 * @param lossProbability the chance a message is lost, 0 to 1
 * @param maxMessageBytes the largest payload, bytes
 */
public record CommsUpdate(Double maxRange, Boolean wallsBlock, Integer latencySteps, Double lossProbability,
                          Integer maxMessageBytes) implements Message {
}
