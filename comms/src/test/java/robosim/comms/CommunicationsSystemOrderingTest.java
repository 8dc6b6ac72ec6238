package robosim.comms;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static robosim.comms.Messages.ids;
import static robosim.comms.Messages.toAll;
import static robosim.comms.Messages.toGroup;
import static robosim.comms.Messages.toRobot;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import robosim.protocol.MessageDelivery;

/** The order of deliveries, and that the same calls give the same deliveries. */
class CommunicationsSystemOrderingTest {
    /** The world's order, neither alphabetical nor the order of the senders below. */
    private static final List<String> ROBOTS = List.of("c", "a", "d", "b");
    private static final Set<String> ALL = Set.copyOf(ROBOTS);
    private final FakePositions positions = new FakePositions()
            .put("a", 0, 0).put("b", 1000, 0).put("c", 2000, 0).put("d", 3000, 0);

    @Test
    void messagesOfOneStepArriveInSubmissionOrder() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, CommsSettings.DEFAULT, 1);
        // neither by sender nor by id: c 7, a 1, b 5, a 2
        comms.submit(3, "c", toRobot(7, "d"));
        comms.submit(3, "a", toAll(1));
        comms.submit(3, "b", toRobot(5, "d"));
        comms.submit(3, "a", toRobot(2, "d"));
        assertEquals(List.of(7L, 1L, 5L, 2L), ids(comms.deliver(3, positions, ALL), "d"));
    }

    @Test
    void broadcastRecipientsComeInWorldOrder() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, CommsSettings.DEFAULT, 1);
        comms.submit(3, "d", toAll(1));
        assertEquals(List.of("c", "a", "b"), List.copyOf(comms.deliver(3, positions, ALL).keySet()));
    }

    @Test
    void multicastRecipientsComeInWorldOrderNotJoiningOrder() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, CommsSettings.DEFAULT, 1);
        comms.join("b", "blue");
        comms.join("a", "blue");
        comms.join("c", "blue");
        comms.submit(3, "d", toGroup(1, "blue"));
        assertEquals(List.of("c", "a", "b"), List.copyOf(comms.deliver(3, positions, ALL).keySet()));
    }

    @Test
    void sameCallsGiveTheSameDeliveries() {
        assertEquals(run(), run());
    }

    /** A mixed run with range, walls, latency and loss; @return each step's deliveries, in order */
    private List<List<Map.Entry<String, List<MessageDelivery>>>> run() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, new CommsSettings(2500, true, 2, 0.5, 100), 99);
        FakePositions moving = new FakePositions()
                .put("a", 0, 0).put("b", 1000, 0).put("c", 2000, 0).put("d", 3000, 0).block("a", "c");
        comms.join("a", "blue");
        comms.join("d", "blue");
        List<List<Map.Entry<String, List<MessageDelivery>>>> steps = new ArrayList<>();
        for (long step = 1; step <= 20; step++) {
            comms.submit(step, "a", toAll(step * 10));
            comms.submit(step, "b", toGroup(step * 10 + 1, "blue"));
            comms.submit(step, "c", toRobot(step * 10 + 2, "a"));
            comms.submit(step, "d", toAll(step * 10 + 3));
            moving.put("d", 3000 - 100 * step, 0);
            steps.add(new ArrayList<>(comms.deliver(step, moving, ALL).entrySet()));
        }
        return steps;
    }
}
