package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.protocol.BatteryReading;
import robosim.protocol.Command;

/**
 * The battery: full at the start, the electronics' 1 A drawing it down, the motors' 2 A per m/s
 * more, and the current sagging the voltage by 0.1 Ω. Worlds step 100 ms.
 */
class BatteryTest {
    private final Simulation sim = new Simulation(Worlds.motorsOn(Worlds.world(20000, 20000, List.of(),
            Worlds.robot("driver", 1000, 5000, 0), Worlds.robot("stander", 1000, 15000, 0))));

    private BatteryReading battery(String robot) {
        return sim.state(robot).get(BatteryReading.PART);
    }

    private void steps(int n, List<Command> driver) {
        for (int i = 0; i < n; i++) {
            sim.step(i == 0 ? Map.of("driver", driver) : Map.of());
        }
    }

    @Test
    void aRobotStartsFullWithTheElectronicsSaggingTheVoltage() {
        assertEquals(new BatteryReading(13.0 - 1.0 * 0.1, 100), battery("driver"));
    }

    @Test
    void standingDrawsTheElectronicsCurrentOnly() {
        steps(600, List.of());
        double drawnAh = 1.0 * 60 / 3600;
        double charge = 1 - drawnAh / 21.6;
        BatteryReading b = battery("stander");
        assertEquals(100 * charge, b.stateOfCharge(), 1e-9);
        assertEquals(11.5 + 1.5 * charge - 0.1, b.volts(), 1e-9);
    }

    @Test
    void drivingSagsTheVoltageAndDrainsTheChargeFaster() {
        steps(600, List.of(new Command.SetVel(500)));
        BatteryReading driving = battery("driver");
        BatteryReading standing = battery("stander");
        assertEquals(500, sim.state("driver").vel(), 1e-9, "the driver is at full speed");
        assertEquals(-2.0 * 0.5 * 0.1, driving.volts() - standing.volts(), 0.01,
                "the motors' 1 A at 0.5 m/s sags the voltage 0.1 V more, and a minute's drain adds a little");
        assertTrue(driving.stateOfCharge() < standing.stateOfCharge(), driving + " vs " + standing);

        steps(100, List.of(new Command.Stop()));
        BatteryReading stopped = battery("driver");
        BatteryReading stood = battery("stander");
        assertTrue(stopped.volts() > driving.volts(), "the sag goes when the motors stop: " + stopped);
        assertTrue(stopped.volts() < stood.volts(), "the charge driven away stays gone: " + stopped + " vs " + stood);
        assertEquals(stood.stateOfCharge() - stopped.stateOfCharge(),
                100 * (stood.volts() - stopped.volts()) / 1.5, 1e-9, "what is gone is the open-circuit voltage's fall");
    }
}
