package robosim.protocol;

import java.util.List;

/**
 * The Environment's answer to a control client's {@code status} request (a {@link ControlRequest}
 * with op {@code status} and no arguments): the run's state and every robot's, as a ControlPanel's
 * table shows them. It is answered at once, between two messages of the step loop, so it is a
 * consistent picture of one moment; it changes nothing.
 *
 * @param id      the request's id
 * @param world   the world's name
 * @param step    the last step run (0 before the first)
 * @param timeMs  simulated time after it, ms
 * @param paused  whether the run is paused (a {@code step N} under way still counts as paused)
 * @param pace    0 for as fast as possible, else the factor of real time in force
 * @param robots  every robot of the world, in the world file's order, then any others
 */
public record RunStatus(long id, String world, long step, long timeMs, boolean paused, double pace,
                        List<RobotStatus> robots) implements Message {
    /** The most robots a status may list. */
    public static final int MAX_ROBOTS = 10_000;

    /**
     * Checks every value so that a hostile peer's status cannot carry a negative step or a NaN pose.
     *
     * @throws IllegalArgumentException naming the value and the rule
     */
    public RunStatus {
        if (world == null) {
            world = "";
        }
        robots = robots == null ? List.of() : List.copyOf(robots);
        if (robots.size() > MAX_ROBOTS) {
            throw new IllegalArgumentException("a run status lists at most " + MAX_ROBOTS + " robots, got " + robots.size());
        }
        atLeastZero("step", step);
        atLeastZero("timeMs", timeMs);
        if (!(pace >= 0 && pace <= 1e6)) {
            throw new IllegalArgumentException("a run status's pace is 0 (as fast as possible) or a factor of real"
                    + " time up to 1e6, got " + pace);
        }
    }

    private static void atLeastZero(String what, long value) {
        if (value < 0) {
            throw new IllegalArgumentException("a run status's " + what + " is 0 or more, got " + value);
        }
    }

    /**
     * One robot as the Environment knows it now.
     *
     * @param name       the robot's name
     * @param type       its type as the world names it (for example {@code p3dx}), or empty
     * @param drivenBy   what drives it: its program's connection (for example {@code program at
     *                   127.0.0.1:40312} or {@code link at ...}), or empty when nothing does
     * @param connected  whether its program is connected now
     * @param x          true x, mm
     * @param y          true y, mm
     * @param th         true heading, degrees
     * @param vel        translational velocity, mm/s
     * @param rotVel     rotational velocity, deg/s
     * @param stalled    whether it is stalled now
     * @param collisions collisions counted since the run started
     * @param sent       messages it sent that the CommunicationsSystem accepted
     * @param received   messages delivered to it
     * @param lastStep   the last step whose requests it sent in time (0 for none)
     */
    public record RobotStatus(String name, String type, String drivenBy, boolean connected, double x, double y,
                              double th, double vel, double rotVel, boolean stalled, long collisions, long sent,
                              long received, long lastStep) {
        /**
         * @throws IllegalArgumentException if the name is missing, a number is not finite or a count is negative
         */
        public RobotStatus {
            if (name == null) {
                throw new IllegalArgumentException("a robot's status names the robot");
            }
            type = type == null ? "" : type;
            drivenBy = drivenBy == null ? "" : drivenBy;
            double[] values = {x, y, th, vel, rotVel};
            for (double v : values) {
                if (!Double.isFinite(v)) {
                    throw new IllegalArgumentException("robot " + RobotHello.printable(name, 40)
                            + "'s status holds a pose or velocity that is not a finite number: " + v);
                }
            }
            long[] counts = {collisions, sent, received, lastStep};
            for (long c : counts) {
                if (c < 0) {
                    throw new IllegalArgumentException("robot " + RobotHello.printable(name, 40)
                            + "'s status holds a negative count: " + c);
                }
            }
        }
    }
}
