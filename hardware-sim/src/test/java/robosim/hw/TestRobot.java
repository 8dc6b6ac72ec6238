package robosim.hw;

import java.util.List;
import robosim.protocol.RobotState;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

/** The smallest concrete robot: AbstractRobot as it is, plus a record of its welcome. */
final class TestRobot extends AbstractRobot {
    static final RobotParameters PARAMETERS = new RobotParameters("Pioneer", "p3dx", 250, 425, 210, 301, 2200, 500,
            300, 300, 100, 100, 0.0056, 5000,
            List.of(new SonarUnit(0, 69, 136, 90), new SonarUnit(1, 114, 119, 50)), 18, 0, 0, 8000);

    volatile RobotState welcomedWith;

    TestRobot(String name, int port) {
        super(name, "127.0.0.1", port, "pioneer", PARAMETERS);
    }

    @Override
    protected void welcomed(RobotState initial) {
        welcomedWith = initial;
    }
}
