package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The smallest bodies and sensor ranges the Environment takes. */
class RobotParameterBoundsTest {
    private static RobotParameters body(double radius, double width, double front, double rear, String shape) {
        RobotParameters p = Messages.p3dx();
        return new RobotParameters(p.robotClass(), p.subclass(), radius, width, front, rear, p.maxVelocity(),
                p.maxRVelocity(), p.transAccel(), p.transDecel(), p.rotAccel(), p.rotDecel(), p.diffConvFactor(),
                p.sonarMaxRange(), p.sonarUnits(), p.laserX(), p.laserY(), p.laserTh(), p.laserMaxRange(), shape, false);
    }

    private static RobotParameters ranges(double sonar, double laser) {
        RobotParameters p = Messages.p3dx();
        return new RobotParameters(p.robotClass(), p.subclass(), p.robotRadius(), p.robotWidth(), p.robotLengthFront(),
                p.robotLengthRear(), p.maxVelocity(), p.maxRVelocity(), p.transAccel(), p.transDecel(), p.rotAccel(),
                p.rotDecel(), p.diffConvFactor(), sonar, List.of(), p.laserX(), p.laserY(), p.laserTh(), laser,
                RobotParameters.RECTANGLE, false);
    }

    @Test
    void noBodyUnderAMillimetre() {
        assertEquals("4.9E-324 was supplied for robotRadius: it must be from 1.0 to 5000.0 mm",
                body(4.9e-324, 425, 210, 301, RobotParameters.RECTANGLE).violation());
        assertEquals("0.5 was supplied for robotWidth: it must be from 1.0 to 5000.0 mm",
                body(250, 0.5, 210, 301, RobotParameters.RECTANGLE).violation());
        assertEquals("0.5 was supplied for robotLengthFront + robotLengthRear: a rectangular body is at least 1.0 mm long",
                body(250, 425, 0.25, 0.25, RobotParameters.RECTANGLE).violation());
        assertEquals("0.0 was supplied for robotRadius: it must be from 1.0 to 5000.0 mm",
                body(0, 425, 210, 301, RobotParameters.RECTANGLE).violation());
        assertEquals("NaN was supplied for robotWidth: it must be from 1.0 to 5000.0 mm",
                body(250, Double.NaN, 210, 301, RobotParameters.RECTANGLE).violation());
        assertNull(body(1, 1, 1, 0, RobotParameters.RECTANGLE).violation(), "a millimetre is enough");
        assertNull(body(1, 1, 0, 0, RobotParameters.ROUND).violation(), "a round body has no length");
    }

    @Test
    void noSensorRangeUnderAMillimetreButASonarMayHaveNone() {
        assertEquals("1.0E-9 was supplied for sonarMaxRange: it must be 0 or from 1.0 to 100000.0 mm",
                ranges(1e-9, 8000).violation());
        assertEquals("0.5 was supplied for laserMaxRange: it must be from 1.0 to 100000.0 mm",
                ranges(5000, 0.5).violation());
        assertNull(ranges(0, 1).violation());
    }
}
