package robosim.hw;

import robosim.protocol.RobotState;

/**
 * What the Environment answered for one step: the robot's pose, velocities, stall and sensor
 * readings, and the step and time they belong to.
 *
 * @param state the robot's state after the step
 */
public record RobotSensorResponse(RobotState state) {
    /** @return the step this response belongs to */
    public long step() {
        return state.step();
    }

    /** @return simulated time, ms */
    public long timeMs() {
        return state.timeMs();
    }
}
