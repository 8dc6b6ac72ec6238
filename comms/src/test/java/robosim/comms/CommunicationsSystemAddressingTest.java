package robosim.comms;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static robosim.comms.Messages.ids;
import static robosim.comms.Messages.toAll;
import static robosim.comms.Messages.toGroup;
import static robosim.comms.Messages.toRobot;

import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;
import robosim.protocol.MessageDelivery;

/** Who receives a message: point to point, multicast groups, broadcast, connected robots only. */
class CommunicationsSystemAddressingTest {
    private static final List<String> ROBOTS = List.of("a", "b", "c", "d");
    private static final Set<String> ALL = Set.copyOf(ROBOTS);
    private final FakePositions positions = new FakePositions()
            .put("a", 0, 0).put("b", 1000, 0).put("c", 2000, 0).put("d", 3000, 0);
    private final CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, CommsSettings.DEFAULT, 1);

    @Test
    void pointToPointReachesOnlyItsRecipient() {
        comms.submit(1, "a", toRobot(7, "c"));
        assertEquals(List.of("c"), List.copyOf(comms.deliver(1, positions, ALL).keySet()));
    }

    @Test
    void multicastReachesTheOtherMembersOnly() {
        comms.join("a", "blue");
        comms.join("b", "blue");
        comms.join("c", "blue");
        comms.join("d", "red");
        comms.submit(1, "a", toGroup(7, "blue"));
        Map<String, List<MessageDelivery>> out = comms.deliver(1, positions, ALL);
        assertEquals(List.of("b", "c"), List.copyOf(out.keySet()), "not the sender a, not d of another group");
        assertEquals(new MessageDelivery("a", Command.Addressing.GROUP, "blue", "text", "m7", 1, 7), out.get("b").get(0));
    }

    @Test
    void multicastFromANonMemberReachesEveryMember() {
        comms.join("b", "blue");
        comms.join("c", "blue");
        comms.submit(1, "a", toGroup(7, "blue"));
        assertEquals(List.of("b", "c"), List.copyOf(comms.deliver(1, positions, ALL).keySet()));
    }

    @Test
    void memberThatLeftGetsNothing() {
        comms.join("b", "blue");
        comms.join("c", "blue");
        comms.leave("b", "blue");
        comms.submit(1, "a", toGroup(7, "blue"));
        assertEquals(List.of("c"), List.copyOf(comms.deliver(1, positions, ALL).keySet()));
    }

    @Test
    void groupMembershipIsTakenAtDelivery() {
        comms.setSettings(Messages.latency(2));
        comms.join("b", "blue");
        comms.submit(1, "a", toGroup(7, "blue"));
        comms.leave("b", "blue");
        comms.join("c", "blue");
        comms.deliver(1, positions, ALL);
        comms.join("d", "blue");
        Map<String, List<MessageDelivery>> out = comms.deliver(2, positions, ALL);
        assertEquals(List.of("c", "d"), List.copyOf(out.keySet()), "b left before delivery, c and d joined before it");
    }

    @Test
    void broadcastReachesEveryRobotButTheSender() {
        comms.submit(1, "b", toAll(7));
        Map<String, List<MessageDelivery>> out = comms.deliver(1, positions, ALL);
        assertEquals(List.of("a", "c", "d"), List.copyOf(out.keySet()));
        assertEquals(new MessageDelivery("b", Command.Addressing.ALL, "*", "text", "m7", 1, 7), out.get("d").get(0));
    }

    @Test
    void disconnectedRobotReceivesNothing() {
        comms.join("b", "blue");
        comms.join("c", "blue");
        comms.submit(1, "a", toAll(7));
        comms.submit(1, "a", toRobot(8, "b"));
        comms.submit(1, "a", toGroup(9, "blue"));
        Map<String, List<MessageDelivery>> out = comms.deliver(1, positions, Set.of("a", "c", "d"));
        assertEquals(List.of(), ids(out, "b"));
        assertEquals(List.of(7L, 9L), ids(out, "c"));
    }

    @Test
    void disconnectedRobotDoesNotGetMissedMessagesOnReconnecting() {
        comms.submit(1, "a", toRobot(7, "b"));
        comms.deliver(1, positions, Set.of("a"));
        assertEquals(Map.of(), comms.deliver(2, positions, ALL));
    }
}
