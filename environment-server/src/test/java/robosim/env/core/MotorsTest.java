package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.env.world.World;
import robosim.protocol.Command;
import robosim.protocol.RobotState;

/** A Pioneer's motor switch: disabled motors ignore motion and say so once; disabling stops. */
class MotorsTest {
    private static World disabledWorld() {
        return new World("test", Path.of("test.xml"), 20000, 20000, 100, List.of(),
                List.of(Worlds.robot("r", 5000, 5000, 0)));
    }

    private static void step(Simulation sim, Command... c) {
        sim.step(Map.of("r", List.of(c)));
    }

    @Test
    void aPioneerConnectsWithItsMotorsDisabled() {
        Simulation sim = new Simulation(disabledWorld());
        sim.setConnected("r", true);
        assertEquals(Boolean.FALSE, sim.state("r").motorsEnabled());
    }

    @Test
    void whileDisabledSetVelAndMoveDoNothingAndTheErrorSaysSoOnce() {
        Simulation sim = new Simulation(disabledWorld());
        sim.setConnected("r", true);
        step(sim, new Command.SetVel(300));
        RobotState s = sim.state("r");
        assertEquals(5000, s.x(), 1e-9);
        assertEquals(0, s.vel(), 1e-9);
        assertEquals(List.of("step 1: motors are disabled: call enableMotors() first; setVel ignored"
                + " (said once until the motors are enabled)"), s.errors());
        step(sim, new Command.Move(1000));
        for (int i = 0; i < 20; i++) {
            step(sim);
        }
        s = sim.state("r");
        assertEquals(5000, s.x(), 1e-9, "the move was ignored too");
        assertEquals(List.of(), s.errors(), "said once for the disabled spell");
    }

    @Test
    void limitsStillTakeEffectWhileDisabled() {
        Simulation sim = new Simulation(disabledWorld());
        sim.setConnected("r", true);
        step(sim, new Command.SetMaxTransVel(100));
        assertEquals(List.of(), sim.state("r").errors());
        step(sim, new Command.SetMotors(true), new Command.SetVel(300));
        for (int i = 0; i < 20; i++) {
            step(sim);
        }
        assertEquals(100, sim.state("r").vel(), 1e-9, "the limit set while disabled holds");
    }

    @Test
    void enabledTheyWork() {
        Simulation sim = new Simulation(disabledWorld());
        sim.setConnected("r", true);
        step(sim, new Command.SetMotors(true), new Command.SetVel(300));
        for (int i = 0; i < 20; i++) {
            step(sim);
        }
        RobotState s = sim.state("r");
        assertEquals(Boolean.TRUE, s.motorsEnabled());
        assertEquals(300, s.vel(), 1e-9);
        assertTrue(s.x() > 5300, "it went ahead: " + s.x());
    }

    @Test
    void disablingWhileMovingStopsAtOnceAndANewSpellIsToldAgain() {
        Simulation sim = new Simulation(disabledWorld());
        sim.setConnected("r", true);
        step(sim, new Command.SetVel(300));
        step(sim, new Command.SetMotors(true), new Command.SetVel(300));
        for (int i = 0; i < 20; i++) {
            step(sim);
        }
        step(sim, new Command.SetMotors(false));
        RobotState s = sim.state("r");
        assertEquals(0, s.vel(), 1e-9, "ENABLE 0 stops the robot");
        assertEquals(Boolean.FALSE, s.motorsEnabled());
        double x = s.x();
        step(sim, new Command.SetVel(300));
        s = sim.state("r");
        assertEquals(x, s.x(), 1e-9);
        assertEquals(1, s.errors().size(), "a new disabled spell is told again: " + s.errors());
    }

    @Test
    void aWorldWithMotorsEnabledStartsThemEnabled() {
        Simulation sim = new Simulation(Worlds.motorsOn(disabledWorld()));
        sim.setConnected("r", true);
        step(sim, new Command.SetVel(300));
        assertEquals(Boolean.TRUE, sim.state("r").motorsEnabled());
        assertTrue(sim.state("r").vel() > 0);
    }

    @Test
    void aProgramThatConnectsAgainFindsTheMotorsAsTheWorldSays() {
        Simulation sim = new Simulation(disabledWorld());
        sim.setConnected("r", true);
        step(sim, new Command.SetMotors(true), new Command.SetVel(300));
        sim.setConnected("r", false);
        sim.setConnected("r", true);
        step(sim);
        assertEquals(Boolean.FALSE, sim.state("r").motorsEnabled());
        assertEquals(0, sim.state("r").vel(), 1e-9);
    }

    @Test
    void aScoutsMotorsAreAlwaysOn() {
        World w = new World("test", Path.of("test.xml"), 20000, 20000, 100, List.of(),
                List.of(new robosim.env.world.RobotSpec("s", "scout", 5000, 5000, 0, Path.of("p3dx.p"), Worlds.p3dx(), 1)));
        Simulation sim = new Simulation(w);
        sim.setConnected("s", true);
        sim.step(Map.of("s", List.of(new Command.SetMotors(false), new Command.SetVel(200))));
        RobotState s = sim.state("s");
        assertEquals(Boolean.TRUE, s.motorsEnabled());
        assertTrue(s.vel() > 0);
        assertFalse(s.errors().stream().anyMatch(e -> e.contains("motors")));
    }
}
