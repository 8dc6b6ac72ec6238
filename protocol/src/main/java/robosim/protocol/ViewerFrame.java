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
     */
    public record RobotView(String name, double x, double y, double th, boolean stalled,
                            boolean connected, int[] sonar) { }
}
