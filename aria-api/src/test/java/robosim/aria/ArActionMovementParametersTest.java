package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;

/** ArActionMovementParameters.cpp's rules: each parameter of size 1 or more is asked for, at full strength. */
class ArActionMovementParametersTest {
    private final ArActionMovementParameters params = new ArActionMovementParameters();

    @Test
    void withItsDefaultsItAsksForNothingButStillAnswers() {
        ArActionDesired d = ActionFixture.fire(params);
        assertNotNull(d);
        assertFalse(d.isAnythingDesired());
    }

    @Test
    void eachParameterGoesToItsChannelTheBackwardSpeedNegated() {
        params.setParameters(300, 200, 150, 400, 50, 60, 70);
        ArActionDesired d = ActionFixture.fire(params);
        assertEquals(300, d.getMaxVel());
        assertEquals(1, d.getMaxVelStrength());
        assertEquals(-200, d.getMaxNegVel());
        assertEquals(150, d.getTransAccel());
        assertEquals(400, d.getTransDecel());
        assertEquals(50, d.getMaxRotVel());
        assertEquals(60, d.getRotAccel());
        assertEquals(70, d.getRotDecel());
        assertEquals(0, d.getVelStrength(), "no velocity itself");
    }

    @Test
    void aParameterUnderOneIsNotAskedFor() {
        params.setParameters(0.5, 0, 0, 0, 0.9);
        ArActionDesired d = ActionFixture.fire(params);
        assertEquals(0, d.getMaxVelStrength());
        assertEquals(0, d.getMaxRotVelStrength());
    }

    @Test
    void theLateralParametersGoToTheLateralChannels() {
        params.setParameters(0, 0, 0, 0, 0, 0, 0, 250, 100, 120);
        ArActionDesired d = ActionFixture.fire(params);
        assertEquals(250, d.getMaxLeftLatVel());
        assertEquals(250, d.getMaxRightLatVel());
        assertEquals(100, d.getLatAccel());
        assertEquals(120, d.getLatDecel());
    }

    @Test
    void disabledItWantsNothingExceptOnceFromASector() {
        params.setParameters(300);
        params.disable();
        assertFalse(params.isEnabled());
        assertNull(ActionFixture.fire(params));
        params.enableOnceFromSector(null);
        assertEquals(300, ActionFixture.fire(params).getMaxVel());
        assertNull(ActionFixture.fire(params), "once only");
        params.enable();
        assertEquals(300, ActionFixture.fire(params).getMaxVel());
    }

    @Test
    void onARobotItsMaximumHoldsALowerPrioritysVelocity() {
        List<Command> sent = new ArrayList<>();
        ArRobot robot = new ArRobot("r", "127.0.0.1", 5000, Cycles.p3dx()) {
            @Override
            protected void request(Command command) {
                sent.add(command);
            }
        };
        params.setParameters(200);
        robot.addAction(params, 100);
        robot.addAction(new ArActionConstantVelocity("go", 400), 50);
        Cycles.cycle(robot, 100, 0, 0, 0);
        assertTrue(sent.contains(new Command.SetVel(200)), sent.toString());
        assertFalse(sent.contains(new Command.SetVel(400)), sent.toString());
    }
}
