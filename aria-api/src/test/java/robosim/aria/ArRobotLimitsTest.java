package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import robosim.protocol.RobotParameters;

/** ARIA's limit setters (ArRobot.cpp's setTransVelMax and its kin): 0 or less is ignored, too much is capped. */
class ArRobotLimitsTest {
    private final ArRobot robot = new ArRobot("r", "127.0.0.1", 5000, "p3dx");

    @Test
    void theLimitsStartAsTheParameterFileSaysThem() {
        RobotParameters p = robot.getParameters();

        assertEquals(p.transAccel(), robot.getTransAccel());
        assertEquals(p.transDecel(), robot.getTransDecel());
        assertEquals(p.rotAccel(), robot.getRotAccel());
        assertEquals(p.rotDecel(), robot.getRotDecel());
        assertEquals(p.maxVelocity(), robot.getTransVelMax());
        assertEquals(p.maxRVelocity(), robot.getRotVelMax());
    }

    @Test
    void aPositiveLimitIsSetAndAnswered() {
        robot.setTransAccel(450);
        robot.setTransDecel(600);
        robot.setRotAccel(90);
        robot.setRotDecel(120);
        robot.setTransVelMax(500);
        robot.setRotVelMax(60);

        assertEquals(450, robot.getTransAccel());
        assertEquals(600, robot.getTransDecel());
        assertEquals(90, robot.getRotAccel());
        assertEquals(120, robot.getRotDecel());
        assertEquals(500, robot.getTransVelMax());
        assertEquals(60, robot.getRotVelMax());
    }

    @Test
    void zeroOrLessIsIgnoredAsAriaIgnoresItInsteadOfSettingAZeroLimit() {
        robot.setTransAccel(450);
        robot.setTransVelMax(500);

        robot.setTransAccel(0);
        robot.setTransAccel(-100);
        robot.setRotDecel(0);
        robot.setTransVelMax(0);
        robot.setRotVelMax(-5);

        assertEquals(450, robot.getTransAccel());
        assertEquals(robot.getParameters().rotDecel(), robot.getRotDecel());
        assertEquals(500, robot.getTransVelMax());
        assertEquals(robot.getParameters().maxRVelocity(), robot.getRotVelMax());
    }

    @Test
    void theOriginalRoboSimNameStillSetsAZeroLimit() {
        robot.setMaxTransVel(0);

        assertEquals(0, robot.getTransVelMax());
    }

    @Test
    void aLimitOverTheMaximumIsCappedToIt() {
        robot.setRotAccel(1e9);
        robot.setTransVelMax(1e6);

        assertEquals(RobotParameters.MAX_ACCELERATION, robot.getRotAccel());
        assertEquals(robot.getParameters().maxVelocity(), robot.getTransVelMax());
    }
}
