package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.comms.CommsSettings;
import robosim.env.world.HeatSource;
import robosim.env.world.Noise;
import robosim.env.world.World;
import robosim.protocol.Command;
import robosim.protocol.MessageDelivery;
import robosim.protocol.RobotState;

/** Messages routed by the simulation: delivered at step boundaries, errors back to the sender. */
class MessagingTest {
    private static Simulation twoRobots(CommsSettings comms, HeatSource gold) {
        World w = new World("w", java.nio.file.Path.of("w.xml"), 10000, 10000, 100,
                List.of(Worlds.box(4900, 0, 5100, 10000)),
                List.of(Worlds.robot("a", 1000, 5000, 0), Worlds.robot("b", 9000, 5000, 180)),
                gold == null ? List.of() : List.of(gold), Noise.NONE, comms, gold);
        Simulation sim = new Simulation(w);
        sim.setConnected("a", true);
        sim.setConnected("b", true);
        return sim;
    }

    private static Command.SendMessage to(String robot, String text) {
        return new Command.SendMessage(1, Command.Addressing.ROBOT, robot, "text", text);
    }

    @Test
    void aMessageSentInAStepArrivesWithTheStateAfterIt() {
        Simulation sim = twoRobots(CommsSettings.DEFAULT, null);
        sim.step(Map.of("a", List.of(to("b", "hello"))));
        List<MessageDelivery> got = sim.state("b").messages();
        assertEquals(1, got.size());
        assertEquals("a", got.get(0).from());
        assertEquals("hello", got.get(0).body());
        assertEquals(1, got.get(0).sentStep());
        sim.step(Map.of());
        assertTrue(sim.state("b").messages().isEmpty(), "delivered once");
        assertTrue(sim.snapshot().messages().isEmpty(), "the snapshot lists this step's sends only");
    }

    @Test
    void theSnapshotListsWhatWasSentAndSaid() {
        Simulation sim = twoRobots(CommsSettings.DEFAULT, null);
        sim.step(Map.of("a", List.of(to("b", "hi"), new Command.Say("on my way"))));
        assertEquals(1, sim.snapshot().messages().size());
        assertEquals("a", sim.snapshot().said().get(0).robot());
        assertEquals("on my way", sim.snapshot().said().get(0).text());
    }

    @Test
    void anUnknownRecipientIsAnErrorForTheSenderAlone() {
        Simulation sim = twoRobots(CommsSettings.DEFAULT, null);
        sim.step(Map.of("a", List.of(to("zed", "hello"))));
        RobotState a = sim.state("a");
        assertEquals(1, a.errors().size());
        assertTrue(a.errors().get(0).contains("'zed'"), a.errors().get(0));
        assertTrue(sim.state("b").errors().isEmpty());
        assertTrue(sim.state("b").messages().isEmpty());
    }

    @Test
    void wallsBlockWhenTheWorldSaysSoAndTheSettingsCanChangeWhileRunning() {
        Simulation sim = twoRobots(new CommsSettings(0, true, 1, 0, 65536), null);
        sim.step(Map.of("a", List.of(to("b", "through the wall?"))));
        assertTrue(sim.state("b").messages().isEmpty(), "the wall at x = 5000 is in the way");
        sim.setCommsSettings(CommsSettings.DEFAULT);
        sim.step(Map.of("a", List.of(to("b", "now"))));
        assertEquals("now", sim.state("b").messages().get(0).body());
    }

    @Test
    void groupsCarryMulticasts() {
        Simulation sim = twoRobots(CommsSettings.DEFAULT, null);
        sim.step(Map.of("b", List.of(new Command.JoinGroup("team"))));
        sim.step(Map.of("a", List.of(new Command.SendMessage(2, Command.Addressing.GROUP, "team", "text", "all of you"))));
        assertEquals("all of you", sim.state("b").messages().get(0).body());
        assertEquals("team", sim.state("b").messages().get(0).to());
    }

    @Test
    void aFindCountsOnlyNearTheGold() {
        Simulation sim = twoRobots(CommsSettings.DEFAULT, new HeatSource(1500, 5000, 50, 1));
        sim.step(Map.of("b", List.of(new Command.ReportFound("gold"))));
        assertNull(sim.find());
        assertTrue(sim.state("b").errors().get(0).contains("mm from it"), sim.state("b").errors().get(0));
        sim.step(Map.of("a", List.of(new Command.ReportFound("gold"))));
        assertNotNull(sim.find());
        assertEquals("a", sim.find().robot());
        assertEquals(2, sim.find().step());
        assertEquals(500, sim.find().distance(), 1e-9);
    }
}
