package robosim.comms;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static robosim.comms.Messages.ids;
import static robosim.comms.Messages.latency;
import static robosim.comms.Messages.toRobot;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;
import robosim.protocol.MessageDelivery;

/** When a message arrives: latency steps after the step it was sent in. */
class CommunicationsSystemLatencyTest {
    private static final List<String> ROBOTS = List.of("a", "b");
    private static final Set<String> ALL = Set.copyOf(ROBOTS);
    private final FakePositions positions = new FakePositions().put("a", 0, 0).put("b", 1000, 0);

    @Test
    void latencyOneDeliversAtTheEndOfTheStepItWasSentIn() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, latency(1), 1);
        comms.submit(5, "a", toRobot(7, "b"));
        assertEquals(List.of(7L), ids(comms.deliver(5, positions, ALL), "b"));
    }

    @Test
    void latencyThreeDeliversTwoStepsLater() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, latency(3), 1);
        comms.submit(5, "a", toRobot(7, "b"));
        assertEquals(List.of(), ids(comms.deliver(5, positions, ALL), "b"));
        assertEquals(List.of(), ids(comms.deliver(6, positions, ALL), "b"));
        assertEquals(List.of(7L), ids(comms.deliver(7, positions, ALL), "b"));
    }

    @Test
    void deliveredMessageIsNotDeliveredAgain() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, latency(1), 1);
        comms.submit(5, "a", toRobot(7, "b"));
        comms.deliver(5, positions, ALL);
        assertEquals(List.of(), ids(comms.deliver(6, positions, ALL), "b"));
        assertEquals(0, comms.inFlight());
    }

    @Test
    void deliveryCarriesTheStepItWasSentIn() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, latency(3), 1);
        comms.submit(5, "a", toRobot(7, "b"));
        MessageDelivery d = comms.deliver(7, positions, ALL).get("b").get(0);
        assertEquals(new MessageDelivery("a", Command.Addressing.ROBOT, "b", "text", "m7", 5, 7), d);
    }

    @Test
    void raisingLatencyDoesNotDelayMessagesAlreadySent() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, latency(1), 1);
        comms.submit(5, "a", toRobot(7, "b"));
        comms.setSettings(latency(3));
        comms.submit(5, "a", toRobot(8, "b"));
        assertEquals(List.of(7L), ids(comms.deliver(5, positions, ALL), "b"));
        assertEquals(List.of(), ids(comms.deliver(6, positions, ALL), "b"));
        assertEquals(List.of(8L), ids(comms.deliver(7, positions, ALL), "b"));
    }

    @Test
    void loweringLatencyDoesNotHastenMessagesAlreadySent() {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, latency(3), 1);
        comms.submit(5, "a", toRobot(7, "b"));
        comms.setSettings(latency(1));
        comms.submit(5, "a", toRobot(8, "b"));
        assertEquals(List.of(8L), ids(comms.deliver(5, positions, ALL), "b"));
        assertEquals(List.of(), ids(comms.deliver(6, positions, ALL), "b"));
        assertEquals(List.of(7L), ids(comms.deliver(7, positions, ALL), "b"));
    }
}
