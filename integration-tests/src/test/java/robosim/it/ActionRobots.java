package robosim.it;

import robosim.aria.ArRobot;

/** Connects the robots of the action tests as an ARIA program connects its robot. */
final class ActionRobots {
    private ActionRobots() {
    }

    /**
     * @param name the robot's name in the world
     * @param port the Environment's robot port
     * @return the robot, connected
     * @throws IllegalStateException if it could not connect
     */
    static ArRobot connect(String name, int port) {
        ArRobot robot = new ArRobot(name, "127.0.0.1", port, "p3dx.xml");
        if (!robot.blockingConnect()) {
            throw new IllegalStateException(robot.getConnectionError());
        }
        return robot;
    }
}
