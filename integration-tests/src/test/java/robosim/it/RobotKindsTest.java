package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import robosim.hw.AbstractRobot;
import robosim.params.RobotParametersReader;
import robosim.params.RobotParameterFiles;
import robosim.protocol.RobotKind;

/** What each robot kind says of itself holds: its API class is a robot, its default parameters are its own. */
class RobotKindsTest {
    @Test
    void eachKindsApiClassIsARobotAndItsDefaultParametersDescribeIt() throws Exception {
        for (RobotKind k : RobotKind.values()) {
            Class<?> api = Class.forName(k.apiClass());
            assertTrue(AbstractRobot.class.isAssignableFrom(api), k + ": " + api);
            String robotClass = RobotParametersReader.read(RobotParameterFiles.resolve(k.defaultParameters())).robotClass();
            assertEquals(k, RobotKind.ofRobotClass(robotClass), k + "'s default parameters are of class " + robotClass);
        }
    }
}
