package robosim.aria;

/**
 * ARIA's older {@code ArSimpleConnector}, kept in ARIA for the programs that use it: a robot
 * connector made from the arguments alone, given its robot when it sets it up. It connects as
 * {@link ArRobotConnector} does, with the same arguments.
 */
public class ArSimpleConnector {
    private final ArRobotConnector robotConnector;

    /** @param parser the program's arguments; the connector's are parsed with everyone's ({@link Aria#parseArgs()}) */
    public ArSimpleConnector(ArArgumentParser parser) {
        this.robotConnector = new ArRobotConnector(parser, null);
    }

    /** @return false if an argument is bad (logged) */
    public boolean parseArgs() {
        return robotConnector.parseArgs();
    }

    /** @param from the arguments @return false if an argument is bad (logged) */
    public boolean parseArgs(ArArgumentParser from) {
        return robotConnector.parseArgs(from);
    }

    /** Logs the options, as the robot connector's. */
    public void logOptions() {
        robotConnector.logOptions();
    }

    /**
     * @param robot the robot
     * @return whether it was told where to connect ({@link ArRobotConnector#setupRobot(ArRobot)})
     */
    public boolean setupRobot(ArRobot robot) {
        return robotConnector.setupRobot(robot);
    }

    /**
     * @param robot the robot
     * @return whether it connected ({@link ArRobotConnector#connectRobot(ArRobot)})
     */
    public boolean connectRobot(ArRobot robot) {
        return robotConnector.connectRobot(robot);
    }

    /** @return whether the robot is simulated: always, once set up */
    public boolean getUsingSim() {
        return robotConnector.getUsingSim();
    }
}
