package robosim.protocol;

import java.util.List;

/**
 * The world's moving parts after one step, sent to every viewer.
 *
 * @param step   the step just completed
 * @param timeMs simulated time after it
 * @param robots every robot of the world, in the world file's order
 */
public record ViewerFrame(long step, long timeMs, List<RobotView> robots) implements Message {
    /** Copies the list so the record stays immutable. */
    public ViewerFrame {
        robots = List.copyOf(robots);
    }

    /**
     * One robot's true pose and status.
     *
     * @param name      the robot's name
     * @param x         true x in mm
     * @param y         true y in mm
     * @param th        true heading in degrees
     * @param stalled   whether it is stalled against something
     * @param connected whether its program is connected
     * @param sonar     its sonar ranges in mm, by index
     * @param odoX      odometry x, mm: where the robot believes it is
     * @param odoY      odometry y, mm
     * @param odoTh     odometry heading, degrees
     * @param laser     its latest laser scan, mm, right to left; empty when off
     * @param laserIncrement degrees between laser readings (1 or 0.5)
     */
    public record RobotView(String name, double x, double y, double th, boolean stalled,
                            boolean connected, int[] sonar, double odoX, double odoY, double odoTh,
                            int[] laser, double laserIncrement) {

        /**
         * A view whose odometry is the true pose and without a laser.
         *
         * @param name      the robot's name
         * @param x         true x, mm
         * @param y         true y, mm
         * @param th        true heading, degrees
         * @param stalled   whether stalled
         * @param connected whether connected
         * @param sonar     sonar ranges, mm
         */
        public RobotView(String name, double x, double y, double th, boolean stalled, boolean connected, int[] sonar) {
            this(name, x, y, th, stalled, connected, sonar, x, y, th, new int[0], 1);
        }
    }
}
