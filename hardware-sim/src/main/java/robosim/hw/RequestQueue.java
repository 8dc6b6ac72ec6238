package robosim.hw;

/**
 * The robot's side of its {@link HardwareSimulator}: where the Robot-Object's code requests a
 * command. Requests wait in the robot's {@code robotRequestQueue} and leave together, as the
 * robot's requests for the open step, once its code has yielded.
 */
public interface RequestQueue {
    /**
     * Queues a request for the open step.
     *
     * @param request what the robot's code asks for
     */
    void request(RobotRequest request);
}
