package robosim.aria;

import robosim.protocol.RobotState;

/**
 * The three poses ARIA's {@code ArRobot} keeps, as rigid frames over the pose the Environment
 * reports: the raw encoder pose ({@code getRawEncoderPose}), the encoder pose
 * ({@code getEncoderPose}: ARIA adds each packet's motion to both, so setting either re-bases it and
 * the motion goes on from there) and the global pose ({@code getPose}, the encoder pose carried by
 * the encoder transform that {@code moveTo}, {@code setEncoderTransform} and
 * {@code setDeadReconPose} set). All start as the identity.
 */
final class PoseFrames {
    private volatile ArTransform stateToRaw = new ArTransform();
    private volatile ArTransform rawToEncoder = new ArTransform();
    private volatile ArTransform encoderToGlobal = new ArTransform();

    static ArPose of(RobotState s) {
        return new ArPose(s.x(), s.y(), s.th());
    }

    ArPose raw(RobotState s) {
        return stateToRaw.doTransform(of(s));
    }

    ArPose encoder(RobotState s) {
        return rawToEncoder.doTransform(raw(s));
    }

    ArPose global(RobotState s) {
        return encoderToGlobal.doTransform(encoder(s));
    }

    ArTransform encoderTransform() {
        return encoderToGlobal;
    }

    void setEncoderTransform(ArTransform t) {
        encoderToGlobal = t;
    }

    /** The raw pose is {@code pose} now; the robot's motion is added to it from here. */
    void setRaw(RobotState s, ArPose pose) {
        ArTransform toRaw = new ArTransform(of(s), pose);
        // the encoder pose stays where it is: re-base its frame over the new raw pose
        ArPose encoder = encoder(s);
        stateToRaw = toRaw;
        rawToEncoder = new ArTransform(raw(s), encoder);
    }

    /** The encoder pose is {@code pose} now; the robot's motion is added to it from here. */
    void setEncoder(RobotState s, ArPose pose) {
        rawToEncoder = new ArTransform(raw(s), pose);
    }

    /**
     * @param heading a heading in the global frame, degrees
     * @return the same heading in the frame of the Environment's pose, in which it turns
     */
    double stateHeading(double heading) {
        double th = encoderToGlobal.getTh() + rawToEncoder.getTh() + stateToRaw.getTh();
        return th == 0 ? heading : ArMath.subAngle(heading, th);
    }
}
