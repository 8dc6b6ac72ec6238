package robosim.comms;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static robosim.comms.Messages.ids;
import static robosim.comms.Messages.toGroup;
import static robosim.comms.Messages.toRobot;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;

/** Messages the CommunicationsSystem refuses, and that it goes on after them. */
class CommunicationsSystemErrorTest {
    private static final List<String> ROBOTS = List.of("a", "b");
    private static final Set<String> ALL = Set.copyOf(ROBOTS);
    private final FakePositions positions = new FakePositions().put("a", 0, 0).put("b", 1000, 0);
    private final CommunicationsSystem comms =
            new CommunicationsSystem(ROBOTS, new CommsSettings(5000, true, 1, 0, 10), 1);

    @Test
    void messageToAnUnknownRobotIsRefusedNamingIt() {
        assertEquals("message 7 is addressed to 'zed', but there is no robot of that name",
                comms.submit(1, "a", toRobot(7, "zed")));
    }

    @Test
    void messageToAGroupNobodyJoinedIsRefusedNamingIt() {
        assertEquals("message 7 is addressed to group 'blue', which no robot has joined",
                comms.submit(1, "a", toGroup(7, "blue")));
    }

    @Test
    void messageToAGroupEveryoneLeftIsRefused() {
        comms.join("b", "blue");
        comms.leave("b", "blue");
        assertNotNull(comms.submit(1, "a", toGroup(7, "blue")));
    }

    @Test
    void oversizeMessageIsRefusedNamingItsSizeAndTheLimit() {
        // five two-byte characters: 10 bytes is at the limit, 12 over it
        assertNull(comms.submit(1, "a", new Command.SendMessage(7, Command.Addressing.ROBOT, "b", "text", "ééééé")));
        assertEquals("message 8 of 12 bytes is over the limit of 10 bytes",
                comms.submit(1, "a", new Command.SendMessage(8, Command.Addressing.ROBOT, "b", "text", "éééééé")));
    }

    @Test
    void refusedMessageIsNotDeliveredAndTheNextOneIs() {
        comms.submit(1, "a", toRobot(6, "zed"));
        comms.submit(1, "a", toGroup(7, "blue"));
        comms.submit(1, "a", new Command.SendMessage(8, Command.Addressing.ROBOT, "b", "text", "more than ten bytes"));
        comms.submit(1, "a", toRobot(9, "b"));
        assertEquals(1, comms.inFlight());
        assertEquals(List.of(9L), ids(comms.deliver(1, positions, ALL), "b"));
    }

    @Test
    void messageFromAnUnknownRobotIsRefusedNamingIt() {
        assertEquals("message 7 is from 'ghost', but there is no robot of that name",
                comms.submit(1, "ghost", toRobot(7, "b")));
        assertEquals(0, comms.inFlight());
    }
}
