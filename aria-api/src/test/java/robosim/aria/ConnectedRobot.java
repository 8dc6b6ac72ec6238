package robosim.aria;

import java.util.ArrayList;
import java.util.List;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.Command;
import robosim.protocol.CameraView;
import robosim.protocol.GripperState;
import robosim.protocol.HeatReading;
import robosim.protocol.RobotState;
import robosim.protocol.RobotStates;

/**
 * A robot that counts as connected, with no Environment: it keeps the commands it sends, in order,
 * and the test drives its cycles by hand. For the calls that send only while the robot is connected
 * (a gripper's), and for checking what any call sends.
 */
final class ConnectedRobot extends ArRobot {
    /** What the robot sent, in order. */
    final List<Command> sent = new ArrayList<>();

    /** @param paramFile the parameter file's name or path, as {@link ArRobot}'s constructor takes it */
    ConnectedRobot(String paramFile) {
        super("r", "127.0.0.1", 5000, paramFile);
    }

    @Override
    public boolean isConnected() {
        return true;
    }

    @Override
    protected void request(Command command) {
        sent.add(command);
    }

    /** @return the last command sent */
    Command last() {
        return sent.get(sent.size() - 1);
    }

    /** One cycle at the origin, standing, reporting a gripper, heat and camera as given (each may be null). */
    void cycle(GripperState gripper, HeatReading heat, CameraView camera) {
        long step = getCounter() + 1;
        responded(new RobotSensorResponse(new RobotState(step, 100 * step, 0, 0, 0, 0, 0, 0, 0, false, 0)
                .with(HeatReading.PART, heat).with(GripperState.PART, gripper).with(CameraView.PART, camera)));
    }

    /** One cycle at a pose, with these wheel velocities. */
    void cycleWheels(double x, double y, double th, double left, double right) {
        long step = getCounter() + 1;
        responded(new RobotSensorResponse(RobotStates.of(step, 100 * step, x, y, th, (left + right) / 2, 0, left, right,
                false, new int[0], 0, new int[0], null)));
    }
}
