package robosim.comms;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static robosim.comms.Messages.ids;
import static robosim.comms.Messages.range;
import static robosim.comms.Messages.toAll;
import static robosim.comms.Messages.toRobot;

import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import robosim.protocol.MessageDelivery;

/** How far a message reaches. */
class CommunicationsSystemRangeTest {
    private static final List<String> ROBOTS = List.of("a", "b", "c");
    private static final Set<String> ALL = Set.copyOf(ROBOTS);

    @Test
    void recipientBeyondRangeGetsNothingOneWithinGetsIt() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, range(5000), 1);
        FakePositions positions = new FakePositions().put("a", 0, 0).put("b", 3000, 4000).put("c", 3000, 4001);
        comms.submit(1, "a", toAll(7));
        Map<String, List<MessageDelivery>> out = comms.deliver(1, positions, ALL);
        assertEquals(List.of(7L), ids(out, "b"), "b is exactly 5000 mm away");
        assertEquals(List.of(), ids(out, "c"), "c is 5000.6 mm away");
    }

    @Test
    void rangeZeroIsUnlimited() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, range(0), 1);
        FakePositions positions = new FakePositions().put("a", 0, 0).put("b", 1e9, -1e9).put("c", 1, 1);
        comms.submit(1, "a", toRobot(7, "b"));
        assertEquals(List.of(7L), ids(comms.deliver(1, positions, ALL), "b"));
    }

    @Test
    void distanceIsMeasuredWhenTheMessageIsDeliveredNotWhenSent() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, range(1000), 1);
        FakePositions positions = new FakePositions().put("a", 0, 0).put("b", 500, 0).put("c", 9000, 0);
        comms.submit(1, "a", toAll(7));
        positions.put("b", 9000, 0).put("c", 500, 0);
        Map<String, List<MessageDelivery>> out = comms.deliver(1, positions, ALL);
        assertEquals(List.of(), ids(out, "b"), "b moved out of range");
        assertEquals(List.of(7L), ids(out, "c"), "c moved into range");
    }

    @Test
    void rangeFollowsTheSenderToo() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, range(1000), 1);
        FakePositions positions = new FakePositions().put("a", 0, 0).put("b", 500, 0).put("c", 0, 0);
        comms.submit(1, "a", toRobot(7, "b"));
        positions.put("a", -600, 0);
        assertEquals(Map.of(), comms.deliver(1, positions, ALL));
    }
}
