package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.env.world.World;
import robosim.geometry.Pose2D;
import robosim.protocol.Command;

/** Robots an open world does not name, added to a simulation under way at spawn poses. */
class SpawnTest {
    private static final List<Pose2D> SPAWNS = List.of(new Pose2D(8000, 2000, 0), new Pose2D(8000, 8000, Math.PI));

    /** A 10 m room cut in two by a wall at x = 5 m, robot a on the left. */
    private static World halves() {
        return Worlds.world(10000, 10000, List.of(Worlds.box(4900, 0, 5100, 10000)), Worlds.robot("a", 2000, 2000, 0));
    }

    /** Runs 40 steps of a driving in a curve; a newcomer is spawned after step 10 when asked. */
    private static RobotSummary run(boolean spawn) {
        Simulation sim = new Simulation(halves(), 7);
        for (int k = 1; k <= 40; k++) {
            Map<String, List<Command>> commands = new HashMap<>();
            commands.put("a", k == 1 ? List.of(new Command.SetVel(300), new Command.SetRotVel(10)) : List.of());
            if (spawn && k > 11) {
                commands.put("b", k == 12 ? List.of(new Command.SetVel(200)) : List.of());
            }
            sim.step(commands);
            if (spawn && k == 10) {
                sim.spawn("b", "pioneer", Worlds.p3dx(), SPAWNS);
            }
        }
        return sim.summary("a");
    }

    @Test
    void aRobotTheWallKeepsApartRunsAsItRunsAlone() {
        assertEquals(run(false), run(true));
    }

    @Test
    void aNewcomerGoesToTheFirstFreePoseAndTheNextToTheOneAfter() {
        Simulation sim = new Simulation(halves());
        sim.step(Map.of());

        assertEquals(SPAWNS.get(0), sim.spawn("b", "pioneer", Worlds.p3dx(), SPAWNS));
        assertEquals(SPAWNS.get(1), sim.spawn("c", "scout", Worlds.p3dx(), SPAWNS));
        assertEquals(List.of("a", "b", "c"), sim.robotNames());
        assertEquals("scout", sim.type("c"));
        assertEquals(List.of("a", "b", "c"), sim.description().robots().stream().map(r -> r.name()).toList());
        assertEquals(1, sim.state("c").step());
    }

    @Test
    void aTakenNameOrNoFreePoseIsRefused() {
        Simulation sim = new Simulation(halves());
        sim.spawn("b", "pioneer", Worlds.p3dx(), SPAWNS.subList(0, 1));

        assertEquals("world w already has a robot named 'a'", assertThrows(IllegalArgumentException.class,
                () -> sim.spawn("a", "pioneer", Worlds.p3dx(), SPAWNS)).getMessage().replaceAll("world \\S+ ", "world w "));
        IllegalArgumentException full = assertThrows(IllegalArgumentException.class,
                () -> sim.spawn("c", "pioneer", Worlds.p3dx(), SPAWNS.subList(0, 1)));
        assertEquals(true, full.getMessage().contains("(1) is taken or too tight for robot c's body"), full.getMessage());
    }

    @Test
    void aSpawnedRobotsResetTakesItBackToItsSpawnPose() {
        Simulation sim = new Simulation(halves());
        sim.spawn("b", "pioneer", Worlds.p3dx(), SPAWNS);
        sim.step(Map.of("b", List.of(new Command.SetVel(300))));
        sim.step(Map.of("b", List.of(new Command.Stop())));
        sim.step(Map.of("b", List.of(new Command.ResetToStart())));

        RobotSummary b = sim.summary("b");
        assertEquals(List.of(8000.0, 2000.0, 0.0), List.of(b.x(), b.y(), b.th()));
    }
}
