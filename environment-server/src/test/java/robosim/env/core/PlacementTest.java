package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.env.world.World;
import robosim.protocol.Command;
import robosim.protocol.RobotState;
import robosim.protocol.TruePose;

/** The simulator's own operations on a robot: placing it (SIM_SET_POSE), resetting it (SIM_RESET), its true pose. */
class PlacementTest {
    private final World world = Worlds.world(10000, 10000, List.of(Worlds.box(7000, 0, 8000, 10000)),
            Worlds.robot("a", 2000, 2000, 0));
    private final Simulation sim = new Simulation(world);

    private void step(Command... commands) {
        sim.step(Map.of("a", List.of(commands)));
    }

    @Test
    void placingMovesTheTruePoseAndLeavesTheOdometry() {
        step(new Command.SetVel(200));
        step();
        RobotState before = sim.state("a");
        step(new Command.Stop(), new Command.SetTruePose(5000, 5000, 90));
        RobotSummary s = sim.summary("a");
        assertEquals(5000, s.x(), 1e-9);
        assertEquals(5000, s.y(), 1e-9);
        assertEquals(90, s.th(), 1e-9);
        RobotState after = sim.state("a");
        assertEquals(before.x(), after.x(), 1e-9, "the odometry stays");
        assertEquals(before.th(), after.th(), 1e-9);
        step(new Command.SetVel(100));
        step();
        // moving along the world's +y now moves the odometry along its own heading, 0°
        assertEquals(before.y(), sim.state("a").y(), 1e-6);
        assertEquals(sim.summary("a").y() - 5000, sim.state("a").x() - before.x(), 1e-6);
    }

    @Test
    void aPlaceInsideSomethingIsRefusedWithTheReason() {
        step(new Command.SetTruePose(7500, 5000, 0));
        assertEquals(2000, sim.summary("a").x(), 1e-9);
        assertEquals(List.of("robot a cannot be placed at (7500, 5000, 0) at step 1: its body would overlap something"
                + " there"), sim.state("a").errors());
    }

    @Test
    void resetPutsTheRobotAndItsOdometryBackAtTheStart() {
        step(new Command.SetVel(300));
        step();
        step(new Command.ResetToStart());
        RobotSummary s = sim.summary("a");
        assertEquals(2000, s.x(), 1e-9);
        assertTrue(s.distance() > 0, "it had moved");
        assertEquals(2000, sim.state("a").x(), 1e-9);
        assertEquals(0, sim.state("a").vel(), 1e-9, "and it stands still");
    }

    @Test
    void theTruePoseIsReportedOnlyWhenAsked() {
        step();
        assertNull(sim.state("a").get(TruePose.PART));
        step(new Command.ReportTruePose(true));
        assertEquals(new TruePose(2000, 2000, 0), sim.state("a").get(TruePose.PART));
    }

    @Test
    void eachAccelerationLimitIsSetOnItsOwn() {
        step(new Command.SetDriveLimit(Command.DriveLimit.TRANS_ACCEL, 100), new Command.SetVel(1000));
        assertEquals(10, sim.state("a").vel(), 1e-9, "100 mm/s² for one step of 0.1 s");
        step(new Command.SetDriveLimit(Command.DriveLimit.TRANS_DECEL, 50), new Command.SetVel(0));
        assertEquals(5, sim.state("a").vel(), 1e-9, "50 mm/s² down");
    }
}
