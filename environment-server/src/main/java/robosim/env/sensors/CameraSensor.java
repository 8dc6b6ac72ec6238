package robosim.env.sensors;

import robosim.env.camera.RobotCamera;
import robosim.protocol.CameraView;
import robosim.protocol.Command;
import robosim.protocol.StateParts;
import robosim.protocol.TruePose;

/**
 * The pan-tilt-zoom camera and its ACTS colour tracking ({@link RobotCamera}), off until the robot
 * configures it or tracks colours: it moves toward where it is pointed and, while tracking, finds
 * the blobs in what it sees of the scenery, the pucks and the other robots.
 */
final class CameraSensor implements Sensor {
    private final RobotCamera camera = new RobotCamera();

    @Override
    public boolean configures(Command.SensorSetting setting) {
        return RobotCamera.handles(setting);
    }

    @Override
    public void configure(Command.SensorSetting setting) {
        camera.configure(setting);
    }

    @Override
    public void sense(SensorInput in) {
        if (camera.isOn()) {
            camera.read(in.pose().x(), in.pose().y(), in.thDeg(), in.dt(), in.scene(), in.bodyId());
        }
    }

    /** @return the camera's view, or null while it is off */
    CameraView view() {
        return camera.view();
    }

    @Override
    public StateParts report(StateParts parts, TruePose truePose) {
        return parts.with(CameraView.PART, camera.view());
    }
}
