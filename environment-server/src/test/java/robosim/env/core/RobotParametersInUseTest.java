package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;
import robosim.params.ParameterFileReader;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarReading;

/** The body, limits and sensor poses simulated are those the robot's program sent. */
class RobotParametersInUseTest {
    private static RobotParameters p3at() {
        return ParameterFileReader.read(Worlds.root().resolve("testLoadFiles/robots/p3at.p"));
    }

    @Test
    void theProgramsParametersReplaceTheWorldFiles() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(Worlds.box(3000, 0, 3100, 10000)),
                Worlds.robot("r", 1000, 5000, 0)));
        assertEquals(2000 - 166, sim.state("r").get(SonarReading.PART).ranges()[3], "p3dx: front sonar 166 mm ahead");
        sim.useParameters("r", p3at());
        assertEquals(2000 - 245, sim.state("r").get(SonarReading.PART).ranges()[3], "p3at: front sonar 245 mm ahead");
        sim.step(Map.of("r", List.of(new Command.SetVel(2000))));
        for (int i = 0; i < 100; i++) {
            sim.step(Map.of());
        }
        assertEquals(3000 - 313, sim.state("r").x(), 0.5, "the p3at's front stops at the wall");
        assertTrue(sim.summary("r").stalled());
    }

    @Test
    void theProgramsSpeedLimitIsTheOneApplied() {
        Simulation sim = new Simulation(Worlds.world(30000, 10000, List.of(), Worlds.robot("r", 1000, 5000, 0)));
        sim.useParameters("r", p3at());
        sim.step(Map.of("r", List.of(new Command.SetVel(2000))));
        for (int i = 0; i < 100; i++) {
            sim.step(Map.of());
        }
        assertEquals(1200, sim.state("r").vel(), 1e-9, "the p3at's MaxVelocity, not the p3dx's 2200");
    }

    @Test
    void aBodyThatWouldOverlapAtTheStartIsRefused() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(Worlds.box(1250, 0, 1350, 10000)),
                Worlds.robot("r", 1000, 5000, 0)));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> sim.useParameters("r", p3at()));
        assertTrue(e.getMessage().contains("overlaps something at its start pose"), e.getMessage());
    }
}
