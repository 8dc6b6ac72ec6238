package robosim.hw;

/**
 * The Environment's side of a {@link HardwareSimulator}: where its {@link EnvironmentLink}
 * delivers each step, on the link's thread.
 */
public interface StepReceiver {
    /**
     * The Environment opened a step: here is the robot's state after the previous one.
     *
     * @param response the state, with the step and time it belongs to
     */
    void step(RobotSensorResponse response);

    /**
     * No more steps will come: the Environment ended the run or the robot's part in it, or it was
     * lost.
     *
     * @param kind   how the robot's part ended
     * @param reason why, for the robot's program
     */
    void ended(RunEnd.Kind kind, String reason);
}
