package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.env.world.RobotSpec;
import robosim.protocol.Bumpers;
import robosim.protocol.Command;
import robosim.protocol.RobotState;
import robosim.protocol.RobotParameters;
import robosim.params.RobotParametersReader;

/** What the Environment does for a Scout: a round body, a bumper ring, wheel moves, accelerations. */
class ScoutCoreTest {
    private static RobotParameters scout() {
        return RobotParametersReader.read(Worlds.root().resolve("testLoadFiles/robots/scout.p"));
    }

    private static RobotSpec scoutAt(double x, double y, double th) {
        return new RobotSpec("s", "scout", x, y, th, Path.of("scout.p"), scout(), 1);
    }

    private static void run(Simulation sim, int steps) {
        for (int i = 0; i < steps; i++) {
            sim.step(Map.of());
        }
    }

    @Test
    void aRoundBodyStopsAtItsRadius() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(Worlds.box(3000, 0, 3100, 10000)),
                scoutAt(1000, 5000, 0)));
        sim.step(Map.of("s", List.of(new Command.SetVel(500))));
        run(sim, 100);
        assertTrue(sim.state("s").stalled());
        assertEquals(3000 - 205, sim.state("s").x(), 0.5, "a 205 mm radius touches the face at x = 3000");
        assertFalse(sim.overlapsAnything("s"));
    }

    @Test
    void theBumperSectorFacingTheContactIsSetAndClearsAfterBackingOff() {
        // the wall ahead-left of the robot: the robot heads 60° towards it, so the contact is at −60°
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(Worlds.box(3000, 0, 3100, 10000)),
                scoutAt(2000, 5000, -60)));
        assertEquals(0, sim.state("s").get(Bumpers.PART).sectors());
        sim.step(Map.of("s", List.of(new Command.SetHeading(-60), new Command.SetVel(300))));
        run(sim, 100);
        RobotState touching = sim.state("s");
        assertTrue(touching.stalled());
        // the wall's normal lies at 0° in the world, +60° relative to the heading of −60°: sector 1
        assertEquals(1 << 1, touching.get(Bumpers.PART).sectors(), Integer.toBinaryString(touching.get(Bumpers.PART).sectors()));
        sim.step(Map.of("s", List.of(new Command.Move(-300))));
        run(sim, 50);
        assertEquals(0, sim.state("s").get(Bumpers.PART).sectors(), "clear after backing off");
    }

    @Test
    void aContactDeadAheadIsSectorZeroAndBehindIsSectorThree() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000,
                List.of(Worlds.box(3000, 0, 3100, 10000), Worlds.box(0, 0, 100, 10000)), scoutAt(2000, 5000, 0)));
        sim.step(Map.of("s", List.of(new Command.SetVel(400))));
        run(sim, 60);
        assertEquals(1, sim.state("s").get(Bumpers.PART).sectors());
        sim.step(Map.of("s", List.of(new Command.SetVel(-400))));
        run(sim, 120);
        assertEquals(1 << 3, sim.state("s").get(Bumpers.PART).sectors());
    }

    @Test
    void equalWheelMovesDriveStraightByThatDistance() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(), scoutAt(2000, 5000, 0)));
        sim.step(Map.of("s", List.of(new Command.MoveWheels(1000, 1000))));
        run(sim, 150);
        assertEquals(3000, sim.state("s").x(), 1);
        assertEquals(5000, sim.state("s").y(), 1e-6);
        assertEquals(0, sim.state("s").vel(), 1e-9);
    }

    @Test
    void oppositeWheelMovesTurnInPlaceByTheArcAngle() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(), scoutAt(2000, 5000, 0)));
        double wheelBase = 2 / scout().diffConvFactor();
        double arc = Math.PI / 2 * wheelBase / 2; // each wheel's travel for a quarter turn
        sim.step(Map.of("s", List.of(new Command.MoveWheels(-arc, arc))));
        run(sim, 150);
        assertEquals(90, sim.state("s").th(), 0.5);
        assertEquals(2000, sim.state("s").x(), 1e-6);
    }

    @Test
    void accelerationsCanBeSet() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(), scoutAt(2000, 5000, 0)));
        sim.step(Map.of("s", List.of(new Command.SetAccel(100, 50), new Command.SetVel(800))));
        assertEquals(10, sim.state("s").vel(), 1e-9, "100 mm/s² over 100 ms");
    }
}
