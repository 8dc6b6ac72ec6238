package robosim.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The speed sliders' bounds come from the parameter file. */
class SpeedLimitsTest {
    @Test
    void theSlidersRunToTheRobotsMaximaAndStartAtAWalkingPace() {
        assertEquals(new SpeedLimits(2200, 500, 300, 30), SpeedLimits.of(Fixtures.robot(2200, 500)));
    }

    @Test
    void aSlowRobotStartsAtItsOwnMaximum() {
        assertEquals(new SpeedLimits(250, 20, 250, 20), SpeedLimits.of(Fixtures.robot(250.7, 20)));
    }
}
