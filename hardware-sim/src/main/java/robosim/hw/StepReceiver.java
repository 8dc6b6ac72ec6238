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
     * No more steps will come: the Environment ended the robot's part in the run, or the link broke.
     *
     * @param reason why, for the robot's program
     */
    void ended(String reason);
}
