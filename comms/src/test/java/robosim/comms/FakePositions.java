package robosim.comms;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;

/** Robot positions from a map, and walls as a set of blocked pairs (either way round). */
final class FakePositions implements Positions {
    private final Map<String, double[]> at = new HashMap<>();
    private final Set<String> blocked = new HashSet<>();

    /** Puts {@code robot} at (x, y), mm, replacing where it was. */
    FakePositions put(String robot, double x, double y) {
        at.put(robot, new double[] {x, y});
        return this;
    }

    /** Puts a wall between {@code a} and {@code b}. */
    FakePositions block(String a, String b) {
        blocked.add(a + "|" + b);
        blocked.add(b + "|" + a);
        return this;
    }

    @Override
    public double[] of(String robot) {
        double[] p = at.get(robot);
        if (p == null) {
            throw new IllegalArgumentException("no position for robot '" + robot + "'");
        }
        return p.clone();
    }

    @Override
    public boolean clear(String from, String to) {
        return !blocked.contains(from + "|" + to);
    }
}
