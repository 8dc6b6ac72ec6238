package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.comms.CommsSettings;
import robosim.protocol.Command;

/** The figures the core counts for every robot: stalls, and the messages it sent, lost and received. */
class RobotFiguresTest {
    private static void run(Simulation sim, int steps) {
        for (int i = 0; i < steps; i++) {
            sim.step(Map.of());
        }
    }

    @Test
    void aRobotThatStaysStalledCountsOneStallAndEachNewStallOneMore() {
        // wall face at x = 3000; the p3dx front is 210 mm ahead of its centre
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(Worlds.box(3000, 0, 3100, 10000)),
                Worlds.robot("r", 1000, 5000, 0)));
        sim.step(Map.of("r", List.of(new Command.SetVel(800))));
        run(sim, 60);
        assertEquals(1, sim.summary("r").stalls(), "pushing on against the wall is one stall");

        sim.step(Map.of("r", List.of(new Command.Move(-500))));
        run(sim, 30);
        assertFalse(sim.summary("r").stalled(), "backed off");
        sim.step(Map.of("r", List.of(new Command.SetVel(400))));
        run(sim, 30);

        RobotSummary r = sim.summary("r");
        assertTrue(r.stalled());
        assertEquals(2, r.stalls());
        assertEquals(2, r.collisions());
    }

    @Test
    void aRobotThatNeverTouchesAnythingHasNoStalls() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(), Worlds.robot("r", 1000, 5000, 0)));
        sim.step(Map.of("r", List.of(new Command.SetVel(300))));
        run(sim, 20);

        assertEquals(0, sim.summary("r").stalls());
    }

    @Test
    void overALossyLinkEveryCopyIsReceivedOrLost() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(), Worlds.robot("a", 2000, 5000, 0),
                Worlds.robot("b", 5000, 5000, 0), Worlds.robot("c", 8000, 5000, 0)));
        for (String r : sim.robotNames()) {
            sim.setConnected(r, true);
        }
        sim.setCommsSettings(new CommsSettings(0, false, 1, 0.4, 65536));
        List<Command> broadcasts = new ArrayList<>();
        for (long id = 1; id <= 200; id++) {
            broadcasts.add(new Command.SendMessage(id, Command.Addressing.ALL, null, "text", "m" + id));
        }
        sim.step(Map.of("a", broadcasts, "b", List.of(new Command.SendMessage(1, Command.Addressing.ROBOT, "nobody",
                "text", "refused"))));

        RobotSummary a = sim.summary("a");
        RobotSummary b = sim.summary("b");
        RobotSummary c = sim.summary("c");
        assertEquals(200, a.messagesSent());
        assertEquals(0, b.messagesSent(), "a message the CommunicationsSystem refused was not sent");
        assertEquals(400, a.messagesLost() + b.messagesReceived() + c.messagesReceived(), "two copies of each");
        assertTrue(a.messagesLost() > 100 && a.messagesLost() < 220, "about 40% of 400: " + a.messagesLost());
        assertEquals(0, a.messagesReceived());
        assertEquals(0, b.messagesLost());
    }

    @Test
    void copiesOutOfRangeAreLostAndRobotsWithoutAProgramDoNotCount() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(), Worlds.robot("a", 2000, 5000, 0),
                Worlds.robot("b", 3000, 5000, 0), Worlds.robot("c", 8000, 5000, 0), Worlds.robot("d", 9000, 5000, 0)));
        sim.setConnected("a", true);
        sim.setConnected("b", true);
        sim.setConnected("c", true);
        sim.setCommsSettings(new CommsSettings(2000, false, 1, 0, 65536));

        sim.step(Map.of("a", List.of(new Command.SendMessage(1, Command.Addressing.ALL, null, "text", "hi"))));

        assertEquals(1, sim.summary("b").messagesReceived());
        assertEquals(1, sim.summary("a").messagesLost(), "c is 6 m away; d has no program");
    }
}
