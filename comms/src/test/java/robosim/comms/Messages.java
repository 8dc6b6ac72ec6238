package robosim.comms;

import java.util.List;
import java.util.Map;

/** Short ways to build messages and read deliveries in tests. */
final class Messages {
    private Messages() {
    }

    static Outgoing toRobot(long id, String robot) {
        return new Outgoing(id, Outgoing.Mode.POINT_TO_POINT, robot, "text", "m" + id);
    }

    static Outgoing toGroup(long id, String group) {
        return new Outgoing(id, Outgoing.Mode.MULTICAST, group, "text", "m" + id);
    }

    static Outgoing toAll(long id) {
        return new Outgoing(id, Outgoing.Mode.BROADCAST, null, "text", "m" + id);
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
    static List<Long> ids(Map<String, List<Delivery>> deliveries, String robot) {
        return deliveries.getOrDefault(robot, List.of()).stream().map(Delivery::id).toList();
    }
}
