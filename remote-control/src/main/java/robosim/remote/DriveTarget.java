package robosim.remote;

import robosim.protocol.RobotParameters;

/**
 * The robot as the RemoteControl drives it: a Pioneer through {@code ArRobot}, or a Scout. Every
 * call only queues a request for the robot's next step, so the window's thread never waits on the
 * network.
 */
public interface DriveTarget {
    /** @return the robot's name in the world */
    String name();

    /** @return the robot's parameters, from its parameter file */
    RobotParameters parameters();

    /**
     * Drives at velocities until the next command.
     *
     * @param vel    translational velocity, mm/s, forward positive
     * @param rotVel rotational velocity, deg/s, counter-clockwise positive
     */
    void drive(double vel, double rotVel);

    /** Stops at once. */
    void stop();

    /** @param distance mm to travel from here, negative backwards */
    void move(double distance);

    /** @param heading the heading to turn to, degrees in [-180, 180] */
    void setHeading(double heading);

    /** @param on whether the sonars fire */
    void sonar(boolean on);

    /**
     * @param on whether the laser scans
     * @return null when done, else why it cannot be (a robot without a laser)
     */
    String laser(boolean on);

    /**
     * @param on whether the heat sensor senses
     * @return null when done, else why it cannot be
     */
    String heat(boolean on);

    /** @param message a checked message to send */
    void send(MessageDraft message);

    /**
     * @return whether the arrow keys step an ARIA keydrive action ({@code ArActionKeydrive}: each
     *         press changes the speed or turns a little) rather than drive while held
     */
    default boolean keydrive() {
        return false;
    }

    /**
     * One arrow-key press for the robot's keydrive action; only called when {@link #keydrive()}.
     *
     * @param key the key pressed (again, when auto-repeat presses it)
     */
    default void keydrive(KeyDrive.Key key) {
        throw new UnsupportedOperationException("robot " + name() + " has no keydrive action");
    }
}
