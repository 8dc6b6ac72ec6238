package robosim.comms;

import java.util.List;
import java.util.Map;
import robosim.protocol.Command;
import robosim.protocol.MessageDelivery;

/** Short ways to build messages and read deliveries in tests. */
final class Messages {
    private Messages() {
    }

    static Command.SendMessage toRobot(long id, String robot) {
        return new Command.SendMessage(id, Command.Addressing.ROBOT, robot, "text", "m" + id);
    }

    static Command.SendMessage toGroup(long id, String group) {
        return new Command.SendMessage(id, Command.Addressing.GROUP, group, "text", "m" + id);
    }

    static Command.SendMessage toAll(long id) {
        return new Command.SendMessage(id, Command.Addressing.ALL, null, "text", "m" + id);
    }

    static CommsSettings range(double maxRange) {
        return new CommsSettings(maxRange, false, 1, 0, 65536);
    }

    static CommsSettings latency(int steps) {
        return new CommsSettings(0, false, steps, 0, 65536);
    }

    static CommsSettings loss(double probability) {
        return new CommsSettings(0, false, 1, probability, 65536);
    }

    /** @return the ids {@code robot} received, in order; empty if it received nothing */
    static List<Long> ids(Map<String, List<MessageDelivery>> deliveries, String robot) {
        return deliveries.getOrDefault(robot, List.of()).stream().map(MessageDelivery::id).toList();
    }
}
