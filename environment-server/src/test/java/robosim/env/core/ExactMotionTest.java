package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;

/**
 * The way covered while a speed changes is the integral of its ramp, so a p3dx (300 mm/s² both
 * ways, 100 deg/s² both ways, 100 ms steps) ends where closed-form kinematics puts it.
 */
class ExactMotionTest {
    private final Simulation sim = new Simulation(Worlds.world(20000, 20000, List.of(),
            Worlds.robot("r", 5000, 5000, 0)));

    private void command(Command... c) {
        sim.step(Map.of("r", List.of(c)));
    }

    private void run(int steps) {
        for (int i = 0; i < steps; i++) {
            sim.step(Map.of());
        }
    }

    private double x() {
        return sim.summary("r").x();
    }

    @Test
    void fromRestTheWayIsHalfATSquaredThenTheHeldSpeed() {
        command(new Command.SetVel(300));
        run(4);
        assertEquals(5000 + 300 * 0.5 * 0.5 / 2, x(), 1e-9, "a·t²/2 after 0.5 s");
        run(5);
        assertEquals(5000 + 150, x(), 1e-9, "v²/2a when 300 mm/s is reached at 1 s");
        run(10);
        assertEquals(5000 + 150 + 300, x(), 1e-9, "then 300 mm/s for 1 s");
    }

    @Test
    void aSpeedReachedPartWayThroughAStepHoldsForTheRestOfIt() {
        command(new Command.SetVel(275));
        run(9);
        // 275 mm/s is reached at 275/300 s, inside the tenth step
        double reached = 275.0 / 300;
        assertEquals(5000 + 275 * 275 / 600.0 + 275 * (1.0 - reached), x(), 1e-9);
        assertEquals(275, sim.state("r").vel(), 1e-9);
    }

    @Test
    void stoppingFrom275TakesVSquaredOverTwoD() {
        command(new Command.SetVel(275));
        run(19);
        double start = x();
        command(new Command.SetVel(0));
        run(20);
        assertEquals(275 * 275 / 600.0, x() - start, 1e-9);
        assertEquals(0, sim.state("r").vel(), 1e-9);
    }

    @Test
    void whileBrakingTheWayIsVTMinusHalfDTSquared() {
        command(new Command.SetVel(300));
        run(19);
        double start = x();
        command(new Command.SetVel(0));
        run(4);
        assertEquals(300 * 0.5 - 300 * 0.5 * 0.5 / 2, x() - start, 1e-9);
    }

    @Test
    void theAngleTurnedWhileTheRotationalSpeedChangesIsItsIntegral() {
        command(new Command.SetRotVel(45));
        run(9);
        double reached = 45.0 / 100;
        assertEquals(45 * 45 / 200.0 + 45 * (1.0 - reached), sim.summary("r").th(), 1e-9);
        double turning = sim.summary("r").th();
        command(new Command.SetRotVel(0));
        run(9);
        assertEquals(45 * 45 / 200.0, sim.summary("r").th() - turning, 1e-9, "stopping turns w²/2d more");
        assertEquals(0, sim.state("r").rotVel(), 1e-9);
    }

    @Test
    void anArcCoversBothIntegrals() {
        command(new Command.SetVel(300), new Command.SetRotVel(45));
        run(9);
        assertEquals(150, sim.summary("r").distance(), 1e-9, "the arc's length is the way");
        assertEquals(45 * 45 / 200.0 + 45 * (1.0 - 0.45), sim.summary("r").th(), 1e-9);
    }

    @Test
    void aMoveStillEndsWhereItShould() {
        command(new Command.Move(1000));
        run(200);
        assertEquals(6000, x(), DriveController.MOVE_DONE);
        assertEquals(0, sim.state("r").vel(), 1e-9);
    }

    @Test
    void aHeadingStillEndsWhereItShould() {
        command(new Command.SetHeading(90));
        run(100);
        assertEquals(90, sim.summary("r").th(), 0.5);
        assertEquals(0, sim.state("r").rotVel(), 1e-9);
    }
}
