package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.function.Predicate;
import org.junit.jupiter.api.Test;
import robosim.env.world.World;
import robosim.env.world.WorldObject;
import robosim.protocol.Command;
import robosim.protocol.GripperState;
import robosim.protocol.LaserReading;
import robosim.protocol.RobotParameters;
import robosim.protocol.RobotState;
import robosim.protocol.Snapshot;
import robosim.protocol.SonarReading;

/** A robot's gripper and the world's pucks, stepped in the simulation core. */
class GripperTest {
    private static final double R = 38;
    private static final RobotParameters GRIPPER = Worlds.p3dx().withGripper(true);
    /** The p3dx's body reaches 210 mm ahead of its centre. */
    private static final double FRONT = 210;

    private static World world(double puckX, RobotParameters p, robosim.env.world.Obstacle... walls) {
        return Worlds.world(10000, 4000, List.of(walls), Worlds.robot("r", 1000, 2000, 0, p))
                .withObjects(List.of(new WorldObject(WorldObject.PUCK, puckX, 2000, R, "red", 1)));
    }

    private static void send(Simulation sim, Command... commands) {
        sim.step(Map.of("r", List.of(commands)));
    }

    /** Steps with no new commands until the state satisfies the test, at most {@code max} steps. */
    private static RobotState until(Simulation sim, int max, Predicate<RobotState> done) {
        for (int i = 0; i < max; i++) {
            RobotState s = sim.state("r");
            if (done.test(s)) {
                return s;
            }
            sim.step(Map.of());
        }
        throw new AssertionError("not done in " + max + " steps: " + sim.state("r"));
    }

    private static Snapshot.ObjectView puck(Simulation sim) {
        return sim.snapshot().objects().get(0);
    }

    @Test
    void aPuckBetweenTheOpenPaddlesBreaksTheInnerBeam() {
        // its centre 50 mm ahead of the body: the inner beam crosses 30 mm ahead, within its radius
        Simulation sim = new Simulation(world(1000 + FRONT + 50, GRIPPER));
        sim.step(Map.of());
        GripperState g = sim.state("r").get(GripperState.PART);
        assertEquals(GripperState.INNER_BEAM, g.switches() & (GripperState.INNER_BEAM | GripperState.OUTER_BEAM));
    }

    @Test
    void aPuckOutsideThePaddlesBreaksNoBeam() {
        Simulation sim = new Simulation(world(1000 + FRONT + 400, GRIPPER));
        sim.step(Map.of());
        assertEquals(0, sim.state("r").get(GripperState.PART).switches() & (GripperState.INNER_BEAM | GripperState.OUTER_BEAM));
    }

    @Test
    void aRobotApproachesGripsLiftsCarriesAPuckTwoMetresAndDropsItWhereItIs() {
        Simulation sim = new Simulation(world(2000, GRIPPER));
        send(sim, new Command.SetVel(150));
        until(sim, 200, s -> (s.get(GripperState.PART).switches() & GripperState.INNER_BEAM) != 0);
        send(sim, new Command.Stop(), new Command.Gripper(Command.Gripper.GRIP_CLOSE));
        RobotState held = until(sim, 50, s -> s.get(GripperState.PART).holding() == 0);
        assertEquals(2, gripState(held.get(GripperState.PART)), "both paddles triggered: ARIA's closed");
        assertEquals("r", puck(sim).heldBy());
        send(sim, new Command.Gripper(Command.Gripper.LIFT_UP));
        until(sim, 50, s -> s.get(GripperState.PART).lift() == 1 && (s.get(GripperState.PART).switches() & GripperState.LIFT_MOVING) == 0);
        assertTrue(puck(sim).lifted());
        RobotSummary before = sim.summary("r");
        Snapshot.ObjectView gripped = puck(sim);
        double ahead = gripped.x() - before.x();
        send(sim, new Command.Move(2000));
        sim.step(Map.of());
        until(sim, 300, s -> s.vel() == 0);
        RobotSummary after = sim.summary("r");
        assertEquals(2000, after.x() - before.x(), 1, "the Move ends within its done distance");
        send(sim, new Command.Gripper(Command.Gripper.LIFT_DOWN));
        until(sim, 50, s -> s.get(GripperState.PART).lift() == 0);
        send(sim, new Command.Gripper(Command.Gripper.GRIP_OPEN));
        until(sim, 50, s -> s.get(GripperState.PART).holding() == -1);
        // backing away leaves it where it was put down
        send(sim, new Command.Move(-500));
        until(sim, 100, s -> s.vel() == 0 && s.step() > 5);
        sim.step(Map.of());
        Snapshot.ObjectView dropped = puck(sim);
        assertNull(dropped.heldBy());
        assertFalse(dropped.lifted());
        // held centred between the paddles, between touching the body and the paddles' tips
        assertTrue(ahead >= FRONT + R && ahead <= FRONT + Grippers.PADDLE_LENGTH, "held " + ahead + " mm ahead");
        // put down where the gripper was: the robot's centre plus the same offset, within 1e-6 mm
        assertEquals(after.x() + ahead, dropped.x(), 1e-6);
        assertEquals(2000, dropped.y(), 1e-6);
        assertEquals(2000, dropped.x() - gripped.x(), 1, "carried 2 m");
    }

    private static int gripState(GripperState g) {
        int d = g.switches();
        return (d & GripperState.LEFT_PADDLE_CLEAR) == 0 && (d & GripperState.RIGHT_PADDLE_CLEAR) == 0 ? 2
                : (d & GripperState.PADDLES_OPEN_CLEAR) == 0 ? 1 : 0;
    }

    @Test
    void aRobotDrivingIntoAPuckPushesItAhead() {
        RobotParameters plain = Worlds.p3dx();
        Simulation sim = new Simulation(world(1500, plain));
        send(sim, new Command.SetVel(300));
        for (int i = 0; i < 50; i++) {
            sim.step(Map.of());
        }
        RobotSummary r = sim.summary("r");
        Snapshot.ObjectView p = puck(sim);
        assertTrue(p.x() > 2000, "pushed from 1500 to " + p.x());
        assertEquals(2000, p.y(), 1e-6, "pushed straight ahead");
        // it stays just ahead of the body: touching, within the push margin and the polygon's corners
        assertEquals(r.x() + FRONT + R, p.x(), Pucks.PUSH_MARGIN + 0.5);
        assertEquals(0, r.collisions());
        assertFalse(r.stalled());
        assertEquals(300, sim.state("r").vel(), 1e-9, "pushing does not slow the robot");
    }

    @Test
    void aPuckAgainstAWallBlocksTheRobotPushingIt() {
        Simulation sim = new Simulation(world(1500, Worlds.p3dx(), Worlds.box(2500, 0, 2600, 4000)));
        send(sim, new Command.SetVel(300));
        for (int i = 0; i < 80; i++) {
            sim.step(Map.of());
        }
        RobotSummary r = sim.summary("r");
        Snapshot.ObjectView p = puck(sim);
        assertEquals(2500 - R, p.x(), 0.5, "stopped at the wall");
        assertEquals(p.x() - R - FRONT, r.x(), Pucks.PUSH_MARGIN + 0.5, "the robot stopped behind it");
        assertTrue(r.stalled());
        assertEquals(1, r.collisions());
    }

    @Test
    void theSonarSeesAPuck() {
        Simulation sim = new Simulation(world(2000, Worlds.p3dx()));
        sim.step(Map.of());
        int[] sonar = sim.state("r").get(SonarReading.PART).ranges();
        // sonar 3 sits 166 mm ahead, 27 mm left, facing 10°: the puck's near side is ~800 mm away
        assertTrue(sonar[3] < 1000 && sonar[3] > 700, "sonar 3 reads " + sonar[3]);
    }

    @Test
    void aRobotWithoutAGripperIsToldSo() {
        Simulation sim = new Simulation(world(2000, Worlds.p3dx()));
        send(sim, new Command.Gripper(Command.Gripper.GRIP_CLOSE));
        RobotState s = sim.state("r");
        assertNull(s.get(GripperState.PART));
        assertEquals(1, s.errors().size());
        assertTrue(s.errors().get(0).contains("has no gripper"), s.errors().get(0));
    }

    @Test
    void aHeldPuckCannotPassThroughAWall() {
        // the puck 50 mm ahead of the body; a wall 600 mm ahead of the robot's centre
        Simulation sim = new Simulation(world(1000 + FRONT + 50, GRIPPER, Worlds.box(1600, 0, 1700, 4000)));
        send(sim, new Command.Gripper(Command.Gripper.GRIP_CLOSE));
        until(sim, 50, s -> s.get(GripperState.PART).holding() == 0);
        send(sim, new Command.SetVel(200));
        for (int i = 0; i < 60; i++) {
            sim.step(Map.of());
        }
        Snapshot.ObjectView p = puck(sim);
        assertEquals("r", p.heldBy());
        assertTrue(p.x() + R <= 1600 + 0.5, "the puck's edge " + (p.x() + R) + " stays out of the wall at 1600");
        assertTrue(sim.summary("r").stalled(), "the robot stopped at the wall, the puck before it");
    }

    @Test
    void theLaserSeesAPuck() {
        Simulation sim = new Simulation(world(2000, Worlds.p3dx()));
        send(sim, new Command.ConfigureLaser(true, 1, 8000));
        int[] scan = sim.state("r").get(LaserReading.PART).ranges();
        // the middle beam, straight ahead from the laser 18 mm ahead of the centre, meets the puck's near side
        assertEquals(1000 - 18 - R, scan[90], 1);
    }
}
