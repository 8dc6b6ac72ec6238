package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;
import robosim.protocol.HeatReading;

/** RoboSim's heat sensor on a robot: switched on when attached, off when detached, read from the state. */
class ArHeatSensorTest {
    private final ConnectedRobot robot = new ConnectedRobot("p3dx");

    @Test
    void itReadsTheStrongestSourceOfTheLatestStateAndNothingWithoutOne() {
        ArHeatSensor heat = new ArHeatSensor(90, 6000);
        assertEquals(90, heat.getFieldOfView());
        assertEquals(6000, heat.getMaxRange());
        heat.attach(robot);
        assertEquals(0, heat.getDistance(), "before the first reading");
        robot.cycle(null, new HeatReading(2.5, -20, 1800), null);
        assertTrue(heat.senses());
        assertEquals(2.5, heat.getIntensity());
        assertEquals(-20, heat.getBearing());
        assertEquals(1800, heat.getDistance());
    }

    @Test
    void detachSwitchesItOffAndTakesItOffTheRobot() {
        ArHeatSensor heat = new ArHeatSensor(120, 4000);
        heat.detach(); // not attached: nothing to do
        assertEquals(List.of(), robot.sent);
        heat.attach(robot);
        robot.cycle(null, new HeatReading(1, 0, 1000), null);
        heat.detach();
        assertEquals(List.of(new Command.ConfigureHeatSensor(true, 120, 4000),
                new Command.ConfigureHeatSensor(false, 120, 4000)), robot.sent);
        assertFalse(heat.senses(), "off its robot it reads nothing");
        assertEquals(0, heat.getDistance());
    }

    @Test
    void aFieldOfViewOrRangeThatBreaksTheRulesIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> new ArHeatSensor(0, 1000));
        assertThrows(IllegalArgumentException.class, () -> new ArHeatSensor(90, -1));
    }
}
