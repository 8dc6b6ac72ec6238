package robosim.protocol;

import java.util.List;

/**
 * The Environment opens step {@code step} for every robot of a shared link (see {@link LinkHello}):
 * the {@link TimeStep}s of all of them in one frame.
 *
 * @param step   the step now open, from 1
 * @param timeMs simulated time at the start of the step
 * @param robots each robot's state after step {@code step - 1}, in the order the robots joined
 */
public record TimeSteps(long step, long timeMs, List<ForRobot> robots) implements Message {
    /** Copies the list so the record stays immutable. */
    public TimeSteps {
        robots = List.copyOf(robots);
    }

    /**
     * One robot's part.
     *
     * @param robot the robot's name
     * @param state its state after the previous step
     */
    public record ForRobot(String robot, RobotState state) {
    }
}
