package robosim.hw;

import robosim.protocol.RobotState;

/**
 * What the Environment answered for one step: the robot's pose, velocities, stall and sensor
 * readings, the step and time they belong to, and the step now open for the robot's requests.
 *
 * @param openStep the step the Environment opened with this response, whose requests it now waits for
 * @param state    the robot's state after the step before it
 */
public record RobotSensorResponse(long openStep, RobotState state) {
    /**
     * The response that opens the step after the state's.
     *
     * @param state the robot's state
     */
    public RobotSensorResponse(RobotState state) {
        this(state.step() + 1, state);
    }

    /** @return the step this response's state belongs to */
    public long step() {
        return state.step();
    }

    /** @return simulated time, ms */
    public long timeMs() {
        return state.timeMs();
    }
}
