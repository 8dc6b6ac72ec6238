package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;
import robosim.protocol.RobotState;
import robosim.protocol.SonarReading;

/**
 * The sonar ring fired in sequence: one transducer of each bank of eight every msPerFiring ms, in
 * index order, as the state marks the new readings. Worlds step 100 ms.
 */
class SonarCycleTest {
    @Test
    void theStateMarksTheNewReadingsAndKeepsTheOthers() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(Worlds.box(3000, 0, 3100, 10000)),
                Worlds.robot("r", 1000, 5000, 0)));
        assertNull(sim.state("r").get(SonarReading.PART).fresh(), "every sonar fires every step until a cycle is set");
        sim.step(Map.of("r", List.of(new Command.SetSonarCycle(40))));
        // the first sequenced reading fires the whole ring
        assertEquals(0xFFFFL, sim.state("r").get(SonarReading.PART).fresh());
        // 200 ms: firings 3, 4, 5 (120, 160, 200 ms); the robot starts towards the wall
        sim.step(Map.of("r", List.of(new Command.SetVel(500))));
        assertEquals(0b0011_1000_0011_1000L, sim.state("r").get(SonarReading.PART).fresh());
        int[] at200 = sim.state("r").get(SonarReading.PART).ranges();
        double x200 = sim.state("r").x();
        // 300 ms: firings 6, 7 (240, 280 ms)
        sim.step(Map.of());
        RobotState s = sim.state("r");
        assertEquals(1L << 6 | 1L << 7 | 1L << 14 | 1L << 15, s.get(SonarReading.PART).fresh());
        assertTrue(s.get(SonarReading.PART).isNew(6));
        assertTrue(!s.get(SonarReading.PART).isNew(3));
        // sonar 3 faces the wall the robot drives towards: not fired, so its range is the old one
        assertTrue(s.x() > x200, "the robot moved on");
        assertEquals(at200[3], s.get(SonarReading.PART).ranges()[3]);
    }

    @Test
    void aCycleOfZeroFiresEveryStepAgain() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(), Worlds.robot("r", 1000, 5000, 0)));
        sim.step(Map.of("r", List.of(new Command.SetSonarCycle(40))));
        sim.step(Map.of("r", List.of(new Command.SetSonarCycle(0))));
        assertNull(sim.state("r").get(SonarReading.PART).fresh());
    }

    @Test
    void aBadCycleIsRefusedNamingTheValueAndTheRule() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Command.SetSonarCycle(-1));
        assertEquals("-1 was supplied for msPerFiring: it is 0 (every step) to 10000 ms", e.getMessage());
    }
}
