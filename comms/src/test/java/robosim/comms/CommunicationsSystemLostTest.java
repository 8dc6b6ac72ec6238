package robosim.comms;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static robosim.comms.Messages.ids;
import static robosim.comms.Messages.loss;
import static robosim.comms.Messages.range;
import static robosim.comms.Messages.toAll;
import static robosim.comms.Messages.toRobot;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** Each copy of a sender's message dropped on the way to a recipient counts against the sender. */
class CommunicationsSystemLostTest {
    private static final List<String> ROBOTS = List.of("a", "b", "c");
    private static final Set<String> ALL = Set.copyOf(ROBOTS);

    @Test
    void aBroadcastOutOfRangeOfOneRecipientLosesOneCopy() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, range(1000), 1);
        FakePositions positions = new FakePositions().put("a", 0, 0).put("b", 900, 0).put("c", 5000, 0);
        comms.submit(1, "a", toAll(1));
        comms.submit(1, "c", toAll(2));

        comms.deliver(1, positions, ALL);

        assertEquals(1, comms.lost("a"), "c is out of a's range");
        assertEquals(2, comms.lost("c"), "a and b are both out of c's range");
        assertEquals(0, comms.lost("b"), "b sent nothing");
    }

    @Test
    void aWallCostsTheCopyItStops() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, new CommsSettings(0, true, 1, 0, 65536), 1);
        FakePositions positions = new FakePositions().put("a", 0, 0).put("b", 1000, 0).put("c", 0, 1000)
                .block("a", "b");
        comms.submit(1, "a", toAll(1));

        comms.deliver(1, positions, ALL);

        assertEquals(1, comms.lost("a"));
    }

    @Test
    void copiesLostByChanceAreTheOnesNotDelivered() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, loss(0.5), 42);
        FakePositions positions = new FakePositions().put("a", 0, 0).put("b", 100, 0).put("c", 200, 0);
        for (long id = 0; id < 1000; id++) {
            comms.submit(1, "a", toRobot(id, "b"));
        }

        int delivered = ids(comms.deliver(1, positions, ALL), "b").size();

        assertEquals(1000 - delivered, comms.lost("a"));
    }

    @Test
    void aRecipientWithoutAProgramLosesNothing() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, range(1000), 1);
        FakePositions positions = new FakePositions().put("a", 0, 0).put("b", 5000, 0).put("c", 5000, 0);
        comms.submit(1, "a", toAll(1));

        comms.deliver(1, positions, Set.of("a", "b"));

        assertEquals(1, comms.lost("a"), "b is out of range; c has no program");
    }

    @Test
    void aMessageNotYetDueIsNotLost() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, new CommsSettings(1000, false, 3, 0, 65536), 1);
        FakePositions positions = new FakePositions().put("a", 0, 0).put("b", 5000, 0).put("c", 500, 0);
        comms.submit(1, "a", toRobot(1, "b"));

        comms.deliver(1, positions, ALL);
        assertEquals(0, comms.lost("a"), "still on its way");
        comms.deliver(3, positions, ALL);
        assertEquals(1, comms.lost("a"));
    }
}
