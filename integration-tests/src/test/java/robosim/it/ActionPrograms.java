package robosim.it;

import robosim.aria.ArRobot;

/** The set-up every robot program of the action tests starts with. */
final class ActionPrograms {
    private ActionPrograms() {
    }

    /**
     * Connects a p3dx as a robot of the world and readies it for actions.
     *
     * @param env  the Environment
     * @param name the robot's name in the world
     * @return the connected robot
     * @throws IllegalStateException saying why it could not connect
     */
    static ArRobot connect(LocalEnvironment env, String name) {
        ArRobot robot = new ArRobot(name, "127.0.0.1", env.robotPort(), "p3dx.xml");
        if (!robot.blockingConnect()) {
            throw new IllegalStateException("robot " + name + " could not connect: " + robot.getConnectionError());
        }
        robot.enableMotors();
        return robot;
    }
}
