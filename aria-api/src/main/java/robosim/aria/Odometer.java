package robosim.aria;

import robosim.protocol.RobotState;

/**
 * ARIA's virtual odometers (ARIA's {@code src/ArRobot.cpp}, where each cycle's encoder pose
 * change is added up): the distance and the degrees a robot has travelled since its program
 * connected, and since the trip odometer was last reset, each the sum of the straight-line
 * distance and of the absolute heading change between one cycle's pose and the next. Times are in
 * simulated seconds. Used on the robot's cycle; read from any thread.
 */
final class Odometer {
    private boolean started;
    private double lastX;
    private double lastY;
    private double lastTh;
    private long startMs;
    private long tripStartMs;
    private long nowMs;
    private double distance;
    private double degrees;
    private double tripDistance;
    private double tripDegrees;

    /** @param s a cycle's state: what the robot travelled since the last one is added */
    synchronized void update(RobotState s) {
        if (started) {
            double d = Math.hypot(s.x() - lastX, s.y() - lastY);
            double deg = Math.abs(ArMath.subAngle(s.th(), lastTh));
            distance += d;
            degrees += deg;
            tripDistance += d;
            tripDegrees += deg;
        } else {
            started = true;
            startMs = s.timeMs();
            tripStartMs = s.timeMs();
        }
        lastX = s.x();
        lastY = s.y();
        lastTh = s.th();
        nowMs = s.timeMs();
    }

    /** Starts the trip odometer again from now. */
    synchronized void resetTrip() {
        tripDistance = 0;
        tripDegrees = 0;
        tripStartMs = nowMs;
    }

    synchronized double distance() {
        return distance;
    }

    synchronized double degrees() {
        return degrees;
    }

    synchronized long seconds() {
        return (nowMs - startMs) / 1000;
    }

    synchronized double tripDistance() {
        return tripDistance;
    }

    synchronized double tripDegrees() {
        return tripDegrees;
    }

    synchronized long tripSeconds() {
        return (nowMs - tripStartMs) / 1000;
    }
}
