package robosim.env.core;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Function;
import robosim.comms.Positions;
import robosim.geometry.GeometryClient;

/**
 * Where the simulation's robots are and what lies between them, for the CommunicationsSystem's
 * range and walls: read when the messages are delivered, at the robots' true poses.
 */
final class RobotPositions implements Positions {
    private final Function<String, SimRobot> robots;
    private final GeometryClient geometry;

    /**
     * @param robots   finds a robot by name
     * @param geometry the world's obstacles and bodies
     */
    RobotPositions(Function<String, SimRobot> robots, GeometryClient geometry) {
        this.robots = robots;
        this.geometry = geometry;
    }

    @Override
    public double[] of(String robot) {
        SimRobot r = robots.apply(robot);
        return new double[] {r.x(), r.y()};
    }

    @Override
    public boolean clear(String from, String to) {
        SimRobot a = robots.apply(from);
        SimRobot b = robots.apply(to);
        return geometry.lineOfSight(a.x(), a.y(), b.x(), b.y());
    }

    /** @return the names of the robots whose programs are connected (the others receive nothing) */
    static Set<String> connected(List<SimRobot> order) {
        Set<String> c = new HashSet<>();
        for (SimRobot r : order) {
            if (r.connected) {
                c.add(r.name);
            }
        }
        return c;
    }
}
