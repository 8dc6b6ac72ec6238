package robosim.env.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

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

        assertEquals("every robot has disconnected", EndConditions.reason(sim, rules, 0));
    }

    @Test
    void aRunThatEndsAfterItsStepsGoesOnWithNoRobotUntilThen() {
        Simulation sim = new Simulation(emptyRoom(new EndRule(EndRule.When.STEPS, 5)));
        SessionRules rules = new SessionRules(sim);
        steps(sim, 4);

        assertNull(EndConditions.reason(sim, rules, 0));
        steps(sim, 1);
        assertEquals("the world's step limit 5 reached", EndConditions.reason(sim, rules, 0));
    }

    @Test
    void theEnvironmentsStepLimitEndsARunWhateverTheWorldSays() {
        Simulation sim = new Simulation(emptyRoom(new EndRule(EndRule.When.STEPS, 50)));
        SessionRules rules = new SessionRules(sim);
        steps(sim, 3);

        assertEquals("step limit 3 reached", EndConditions.reason(sim, rules, 3));
    }

    @Test
    void aRunThatEndsWhenAnyLeavesEndsAtTheFirstDeparture() {
        Simulation sim = new Simulation(emptyRoom(new EndRule(EndRule.When.ANY_LEFT, 0)));
        SessionRules rules = new SessionRules(sim);
        rules.connectedRobots().put("r1", null);
        rules.connectedRobots().put("r2", null);
        rules.start();
        assertNull(EndConditions.reason(sim, rules, 0));

        rules.drop("r2", "removed by control client c after step 0");

        assertEquals("robot r2 dropped at step 0: removed by control client c after step 0 (the world ends the run"
                + " when any robot leaves)", EndConditions.reason(sim, rules, 0));
    }

    @Test
    void aRunThatEndsWhenAllLeftDoesNotEndWhileOneIsConnected() {
        Simulation sim = new Simulation(emptyRoom(new EndRule(EndRule.When.ALL_LEFT, 0)));
        SessionRules rules = new SessionRules(sim);
        rules.connectedRobots().put("r1", null);
        rules.connectedRobots().put("r2", null);
        rules.start();
        rules.drop("r2", "removed");

        assertNull(EndConditions.reason(sim, rules, 0));
        rules.drop("r1", "removed");
        assertEquals("every robot has disconnected", EndConditions.reason(sim, rules, 0));
    }
}
