package robosim.protocol;

/**
 * The Environment is still there: sent to a robot's connection, or a shared link, on which it has
 * sent nothing for about a second (before the first step while other robots are still connecting,
 * or while a slow robot holds a step up). A robot ignores it, except that it restarts the robot's
 * count of the Environment's silence: a robot that hears nothing, neither a step nor a keep-alive,
 * for its lost time declares the Environment lost.
 *
 * @param step the last step the Environment ran; 0 before the first
 */
public record KeepAlive(long step) implements Message {
}
