package robosim.comms;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static robosim.comms.Messages.ids;
import static robosim.comms.Messages.toAll;

import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import robosim.protocol.MessageDelivery;

/** Whether walls stop messages. */
class CommunicationsSystemWallsTest {
    private static final List<String> ROBOTS = List.of("a", "b", "c");
    private static final Set<String> ALL = Set.copyOf(ROBOTS);
    private final FakePositions positions = new FakePositions()
            .put("a", 0, 0).put("b", 1000, 0).put("c", 0, 1000).block("a", "b");

    @Test
    void wallBetweenSenderAndRecipientStopsTheMessageWhenWallsBlock() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, new CommsSettings(0, true, 1, 0, 65536), 1);
        comms.submit(1, "a", toAll(7));
        Map<String, List<MessageDelivery>> out = comms.deliver(1, positions, ALL);
        assertEquals(List.of(), ids(out, "b"), "a wall stands between a and b");
        assertEquals(List.of(7L), ids(out, "c"), "nothing stands between a and c");
    }

    @Test
    void wallBetweenSenderAndRecipientIsIgnoredWhenWallsDoNotBlock() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, new CommsSettings(0, false, 1, 0, 65536), 1);
        comms.submit(1, "a", toAll(7));
        assertEquals(List.of(7L), ids(comms.deliver(1, positions, ALL), "b"));
    }
}
