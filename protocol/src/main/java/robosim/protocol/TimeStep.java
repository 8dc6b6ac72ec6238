package robosim.protocol;

/**
 * The Environment opens step {@code step}: here is the robot's state after the previous step; send
 * your requests for this one.
 *
 * @param step   the step now open, from 1
 * @param timeMs simulated time at the start of the step
 * @param state  the robot's state after step {@code step - 1}
 */
public record TimeStep(long step, long timeMs, RobotState state) implements Message {
}
