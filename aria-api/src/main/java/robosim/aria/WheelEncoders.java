package robosim.aria;

import robosim.protocol.RobotState;

/**
 * The wheel encoder counts ARIA's encoder packets give ({@code ArRobot::getLeftEncoder},
 * {@code requestEncoderPackets}, ArRobot.cpp), simulated: while the packets are requested each
 * cycle adds each wheel's travel since the last, in encoder ticks of the parameter file's
 * {@code DistConvFactor} (mm per tick). Before the first request the counts are 0, as ARIA's are
 * before the first encoder packet.
 */
final class WheelEncoders {
    private final double mmPerTick;
    private boolean requested;
    private long lastMs = -1;
    private double left;
    private double right;

    /** @param mmPerTick the parameter file's {@code DistConvFactor}; ARIA's 1 when it is not above 0 */
    WheelEncoders(double mmPerTick) {
        this.mmPerTick = mmPerTick > 0 ? mmPerTick : 1;
    }

    synchronized void update(RobotState s) {
        if (requested && lastMs >= 0 && s.timeMs() > lastMs) {
            double dt = (s.timeMs() - lastMs) / 1000.0;
            left += s.leftVel() * dt / mmPerTick;
            right += s.rightVel() * dt / mmPerTick;
        }
        lastMs = s.timeMs();
    }

    synchronized void setRequested(boolean on) {
        requested = on;
    }

    synchronized boolean requested() {
        return requested;
    }

    synchronized long left() {
        return Math.round(left);
    }

    synchronized long right() {
        return Math.round(right);
    }
}
