package robosim.aria;

import robosim.protocol.PtzModel;

/**
 * The Canon VC-C4 pan-tilt-zoom camera, with ARIA's figures (ArVCC4.h, ArVCC4.cpp): pan −98° to
 * 98°, tilt −30° to 88°, zoom 0 to 1960, a horizontal field of view of 45° at zoom 0 and 1.97° at
 * 1960, slewing at 90 deg/s pan and 69 deg/s tilt. See {@link ArPTZ}.
 */
public final class ArVCC4 extends ArPTZ {
    /** @param robot the robot that carries it; switch it on with {@link #init()} */
    public ArVCC4(ArRobot robot) {
        super(robot, PtzModel.VCC4);
    }

    @Override
    public String getTypeName() {
        return "vcc4";
    }

    /** @return the fastest pan slew, deg/s (ArVCC4.h's MAX_PAN_SLEW) */
    public double getMaxPanSlew() {
        return getMaxPanSpeed();
    }

    /** @return the fastest tilt slew, deg/s (ArVCC4.h's MAX_TILT_SLEW) */
    public double getMaxTiltSlew() {
        return getMaxTiltSpeed();
    }
}
