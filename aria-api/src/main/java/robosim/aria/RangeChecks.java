package robosim.aria;

import java.util.List;

/**
 * The robot-wide range checks the actions use, over every range device attached to the robot
 * ({@link ArRobot#getRangeDeviceList()}), as ARIA's {@code ArRobot::checkRangeDevicesCurrentPolar}
 * and {@code checkRangeDevicesCurrentBox} (ArRobot.cpp, with ArRangeBuffer.cpp's box rule) answer
 * them: the closest current reading of any device, or -1 when the robot has no range device.
 */
final class RangeChecks {
    private RangeChecks() {
    }

    /**
     * The closest current reading in a slice around the robot, as ARIA's
     * {@code checkRangeDevicesCurrentPolar}.
     *
     * @param robot      the robot
     * @param startAngle degrees, relative to the robot's heading
     * @param endAngle   degrees, relative to the robot's heading
     * @param angleOut   null, or an array whose element 0 receives the closest reading's angle
     * @return the distance from the robot's centre, mm (a device with no reading in the slice
     *         answers its maximum range); -1 without range devices
     */
    static double currentPolar(ArRobot robot, double startAngle, double endAngle, double[] angleOut) {
        double closest = -1;
        double[] angle = new double[1];
        for (ArRangeDevice device : robot.getRangeDeviceList()) {
            angle[0] = Double.NaN;
            double d = device.currentReadingPolar(startAngle, endAngle, angle);
            if (closest < 0 || d < closest) {
                closest = d;
                if (angleOut != null) {
                    angleOut[0] = angle[0];
                }
            }
        }
        return closest;
    }

    /**
     * The closest current reading inside a box of the robot's frame (x forward, y left), as ARIA's
     * {@code checkRangeDevicesCurrentBox}: the corners may come in any order, a reading on an edge
     * counts, and the distance is from the robot's centre.
     *
     * @param robot      the robot
     * @param x1         one corner's x, mm
     * @param y1         one corner's y, mm
     * @param x2         the opposite corner's x, mm
     * @param y2         the opposite corner's y, mm
     * @param readingPos null, or a pose set to the closest reading, in the robot's frame
     * @return the distance, mm (a device with nothing in the box answers its maximum range); -1
     *         without range devices
     */
    static double currentBox(ArRobot robot, double x1, double y1, double x2, double y2, ArPose readingPos) {
        double minX = Math.min(x1, x2);
        double maxX = Math.max(x1, x2);
        double minY = Math.min(y1, y2);
        double maxY = Math.max(y1, y2);
        ArPose at = robot.getPose();
        double cos = Math.cos(ArMath.degToRad(at.getTh()));
        double sin = Math.sin(ArMath.degToRad(at.getTh()));
        double closest = -1;
        for (ArRangeDevice device : robot.getRangeDeviceList()) {
            double deviceClosest = device.getMaxRange();
            List<ArPose> readings = device.getCurrentBuffer();
            for (ArPose r : readings) {
                double dx = r.getX() - at.getX();
                double dy = r.getY() - at.getY();
                double x = cos * dx + sin * dy;
                double y = -sin * dx + cos * dy;
                if (x >= minX && x <= maxX && y >= minY && y <= maxY) {
                    double d = Math.hypot(x, y);
                    if (d < deviceClosest) {
                        deviceClosest = d;
                        if (readingPos != null && (closest < 0 || d < closest)) {
                            readingPos.setPose(x, y, 0);
                        }
                    }
                }
            }
            if (closest < 0 || deviceClosest < closest) {
                closest = deviceClosest;
            }
        }
        return closest;
    }
}
