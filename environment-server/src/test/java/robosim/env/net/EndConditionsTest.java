package robosim.env.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.env.core.Simulation;
import robosim.env.world.EndRule;
import robosim.env.world.RunRules;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.Command;

/**
 * When a run ends of itself under each of the world's end rules, with {@code empty-room.xml}'s r1
 * and r2 marked connected or gone through the session rules (no sockets: robots are only counted).
 */
class EndConditionsTest {
    private static World emptyRoom(EndRule end) {
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (!Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        World w = WorldReader.read(p.resolve("testLoadFiles/environment/empty-room.xml"));
        return w.withRules(new RunRules(end, false, List.of()));
    }

    private static void steps(Simulation sim, int n) {
        for (int i = 0; i < n; i++) {
            sim.step(Map.of());
        }
    }

    @Test
    void byDefaultARunWithNoRobotLeftEnds() {
        Simulation sim = new Simulation(emptyRoom(EndRule.DEFAULT));
        SessionRules rules = new SessionRules(sim);

        assertEquals(new EndOfRun(RunEnding.ALL_GONE, "every robot has disconnected"),
                EndConditions.ending(sim, rules, 0));
    }

    @Test
    void aRunThatEndsAfterItsStepsGoesOnWithNoRobotUntilThen() {
        Simulation sim = new Simulation(emptyRoom(new EndRule(EndRule.When.STEPS, 5)));
        SessionRules rules = new SessionRules(sim);
        steps(sim, 4);

        assertNull(EndConditions.ending(sim, rules, 0));
        steps(sim, 1);
        assertEquals(new EndOfRun(RunEnding.WORLD_STEP_LIMIT, "the world's step limit 5 reached"),
                EndConditions.ending(sim, rules, 0));
    }

    @Test
    void theEnvironmentsStepLimitEndsARunWhateverTheWorldSays() {
        Simulation sim = new Simulation(emptyRoom(new EndRule(EndRule.When.STEPS, 50)));
        SessionRules rules = new SessionRules(sim);
        steps(sim, 3);

        assertEquals(new EndOfRun(RunEnding.STEP_LIMIT, "step limit 3 reached"), EndConditions.ending(sim, rules, 3));
    }

    @Test
    void aRunThatEndsWhenAnyLeavesEndsAtTheFirstDeparture() {
        Simulation sim = new Simulation(emptyRoom(new EndRule(EndRule.When.ANY_LEFT, 0)));
        SessionRules rules = new SessionRules(sim);
        rules.connectedRobots().put("r1", null);
        rules.connectedRobots().put("r2", null);
        rules.start();
        assertNull(EndConditions.ending(sim, rules, 0));

        rules.drop("r2", "removed by control client c after step 0");

        assertEquals(new EndOfRun(RunEnding.ROBOT_LEFT, "robot r2 dropped at step 0: removed by control client c after"
                + " step 0 (the world ends the run when any robot leaves)"), EndConditions.ending(sim, rules, 0));
    }

    @Test
    void aRunThatEndsWhenAllLeftDoesNotEndWhileOneIsConnected() {
        Simulation sim = new Simulation(emptyRoom(new EndRule(EndRule.When.ALL_LEFT, 0)));
        SessionRules rules = new SessionRules(sim);
        rules.connectedRobots().put("r1", null);
        rules.connectedRobots().put("r2", null);
        rules.start();
        rules.drop("r2", "removed");

        assertNull(EndConditions.ending(sim, rules, 0));
        rules.drop("r1", "removed");
        assertEquals(new EndOfRun(RunEnding.ALL_GONE, "every robot has disconnected"),
                EndConditions.ending(sim, rules, 0));
    }

    @Test
    void aRobotsRequestEndsTheRunAfterTheStepItCameInWithItsReason() {
        Simulation sim = new Simulation(emptyRoom(EndRule.DEFAULT));
        SessionRules rules = new SessionRules(sim);
        rules.connectedRobots().put("r1", null);
        rules.connectedRobots().put("r2", null);
        rules.start();
        steps(sim, 811);
        assertNull(EndConditions.ending(sim, rules, 0));

        sim.step(Map.of("r2", List.of(new Command.EndRun("gold found")),
                "r1", List.of(new Command.EndRun("me first"))));

        assertEquals(new EndOfRun(RunEnding.ROBOT_ENDED, "ended by robot r1 at step 812: me first"),
                EndConditions.ending(sim, rules, 0), "r1 comes before r2 in the world: its request is the first");
    }

    @Test
    void aRobotsRequestIsTheEndingEvenWhenTheStepLimitFallsOnItsStep() {
        Simulation sim = new Simulation(emptyRoom(EndRule.DEFAULT));
        SessionRules rules = new SessionRules(sim);
        rules.connectedRobots().put("r1", null);
        rules.start();

        sim.step(Map.of("r1", List.of(new Command.EndRun("done"))));

        assertEquals(new EndOfRun(RunEnding.ROBOT_ENDED, "ended by robot r1 at step 1: done"),
                EndConditions.ending(sim, rules, 1));
    }

    @Test
    void everyEndingHasAStableLowerCaseNameThatReadsBack() {
        assertEquals("gold-found", RunEnding.GOLD_FOUND.wireName());
        assertEquals("robot-ended", RunEnding.ROBOT_ENDED.wireName());
        for (RunEnding e : RunEnding.values()) {
            assertTrue(e.wireName().matches("[a-z]+(-[a-z]+)*"), e.wireName());
            assertEquals(e, RunEnding.ofWireName(e.wireName()));
        }
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class,
                () -> RunEnding.ofWireName("GOLD_FOUND"));
        assertEquals("'GOLD_FOUND' was supplied for a run's ending: it is one of step-limit, world-step-limit,"
                + " gold-found, robot-ended, all-gone, robot-left, stopped, not-started, failed", bad.getMessage());
    }
}
