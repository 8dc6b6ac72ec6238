package robosim.aria;

import robosim.protocol.PtzModel;

/**
 * The Sony EVI-D30 pan-tilt-zoom camera, with ARIA 2.x's ArSonyPTZ figures: pan −95° to 95°, tilt
 * −25° to 25°, zoom 0 to 1023, a horizontal field of view of 48.8° at zoom 0 and 4.4° at 1023. ARIA
 * names no speed for it; it moves at the D30's 80 deg/s pan and 50 deg/s tilt. See {@link ArPTZ}.
 */
public final class ArSonyPTZ extends ArPTZ {
    /** @param robot the robot that carries it; switch it on with {@link #init()} */
    public ArSonyPTZ(ArRobot robot) {
        super(robot, PtzModel.SONY);
    }

    @Override
    public String getTypeName() {
        return "sony";
    }
}
