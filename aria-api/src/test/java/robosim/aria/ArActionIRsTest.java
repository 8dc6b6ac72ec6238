package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;

/**
 * ArActionIRs.cpp and ArActionLimiterTableSensor.cpp on a robot without table-sensing IRs, as every
 * simulated one is: nothing, even driving fast.
 */
class ArActionIRsTest {
    private final ActionFixture f = new ActionFixture();

    @Test
    void withoutIRsItNeverBacksOff() {
        ArActionIRs irs = f.attach(new ArActionIRs());
        for (int i = 0; i < 5; i++) {
            f.at(0, 0, 0, 400);
            assertNull(ActionFixture.fire(irs));
        }
    }

    @Test
    void itListsARIAsParameters() {
        ArActionIRs irs = new ArActionIRs("irs", 150, 4000, 2000, true);
        assertEquals(4, irs.getNumArgs());
        assertEquals("back off speed", irs.getArg(0).getName());
        assertEquals(150, irs.getArg(0).getDouble());
        assertEquals(2000, irs.getArg(2).getInt());
    }

    @Test
    void withoutTableSensorsTheLimiterLeavesTheSpeedAlone() {
        ArActionLimiterTableSensor table = f.attach(new ArActionLimiterTableSensor());
        f.at(0, 0, 0, 400);
        assertNull(ActionFixture.fire(table));
        assertEquals("TableSensorLimiter", table.getName());
    }
}
