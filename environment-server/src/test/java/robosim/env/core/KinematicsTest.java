package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;
import robosim.protocol.RobotState;

class KinematicsTest {
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

    @Test
    void move1000EndsWithin40mmOf1000mmAhead() {
        command(new Command.Move(1000));
        run(200);
        RobotState s = sim.state("r");
        assertEquals(6000, s.x(), 40);
        assertEquals(5000, s.y(), 1e-6);
        assertEquals(0, s.vel(), 1e-9, "the robot has stopped");
    }

    @Test
    void moveBackwardsDrivesBackwardsWithoutTurning() {
        command(new Command.Move(-500));
        run(200);
        RobotState s = sim.state("r");
        assertEquals(4500, s.x(), 40);
        assertEquals(0, s.th(), 1e-9);
    }

    @Test
    void setHeading90EndsWithin3Degrees() {
        command(new Command.SetHeading(90));
        run(100);
        RobotState s = sim.state("r");
        assertEquals(90, s.th(), 3);
        assertEquals(5000, s.x(), 1e-6, "turning in place does not move the centre");
    }

    @Test
    void deltaHeadingIsRelativeToTheHeadingWhenItArrives() {
        command(new Command.SetHeading(170));
        run(100);
        command(new Command.SetDeltaHeading(20));
        run(100);
        assertEquals(-170, sim.state("r").th(), 3, "170 + 20 wraps to -170");
    }

    @Test
    void equalWheelSpeedsDriveStraight() {
        command(new Command.SetVel2(300, 300));
        run(30);
        RobotState s = sim.state("r");
        assertTrue(s.x() > 5500, "moved ahead: " + s.x());
        assertEquals(5000, s.y(), 1e-6);
        assertEquals(0, s.th(), 1e-9);
        assertEquals(300, s.vel(), 1e-6);
    }

    @Test
    void oppositeWheelSpeedsTurnInPlace() {
        command(new Command.SetVel2(-100, 100));
        run(10);
        RobotState s = sim.state("r");
        assertEquals(5000, s.x(), 1e-6);
        assertEquals(5000, s.y(), 1e-6);
        assertTrue(s.th() > 5, "turned counter-clockwise: " + s.th());
        double expected = Math.toDegrees(200 / 2.0 * 0.0056);
        assertEquals(expected, s.rotVel(), 1e-6, "ARIA: (right - left) / 2 x DiffConvFactor");
    }

    @Test
    void velocityIsClampedToTheMaximumAndLimitedByAcceleration() {
        command(new Command.SetMaxTransVel(400), new Command.SetVel(1000));
        assertEquals(30, sim.state("r").vel(), 1e-9, "300 mm/s² over one 100 ms step");
        run(30);
        assertEquals(400, sim.state("r").vel(), 1e-9);
    }

    @Test
    void stopHaltsAtOnce() {
        command(new Command.SetVel(500));
        run(30);
        command(new Command.Stop());
        assertEquals(0, sim.state("r").vel(), 1e-9);
        double x = sim.state("r").x();
        run(5);
        assertEquals(x, sim.state("r").x(), 1e-9);
        assertFalse(sim.state("r").stalled());
    }

    @Test
    void rotationalVelocityTurnsCounterClockwise() {
        command(new Command.SetRotVel(30));
        run(40);
        assertEquals(30, sim.state("r").rotVel(), 1e-9);
        assertTrue(sim.state("r").th() > 30);
    }
}
