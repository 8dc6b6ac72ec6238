package robosim.env.core;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robosim.env.world.HeatSource;
import robosim.env.world.World;
import robosim.protocol.Command;
import robosim.protocol.Snapshot;

/**
 * The run's log, part of {@link Simulation}: what robots said in the step under way, the first
 * confirmed find of the world's gold (a report counts within {@link Simulation#GOLD_FOUND_DISTANCE}
 * of it; any other is answered with an error the robot reads next), the metrics each robot reported
 * (the last value of each name, at most {@value Command.ReportMetric#MAX_METRICS} names a robot; a
 * new name past them is answered with an error) and the first request to end the run.
 */
final class RunEvents {
    private final World world;
    private final MessageRouter messages;
    private final List<Snapshot.Said> said = new ArrayList<>();
    /** Robot, then metric, in the order each was first reported. */
    private final Map<String, Map<String, Double>> metrics = new LinkedHashMap<>();
    /** The metrics reported in the step under way, by robot and name; the last report of the step counts. */
    private final Map<String, Snapshot.Metric> reported = new LinkedHashMap<>();
    private Find find;
    private Snapshot.EndRequest endRequest;

    RunEvents(World world, MessageRouter messages) {
        this.world = world;
        this.messages = messages;
    }

    /** A step begins: what was said and reported in the one before is forgotten. */
    void newStep() {
        said.clear();
        reported.clear();
    }

    /** Takes a robot's run event, in the order it sent it. */
    void take(SimRobot r, Command.RunEvent e, long current) {
        if (e instanceof Command.Say say) {
            said.add(new Snapshot.Said(r.name, say.text()));
        } else if (e instanceof Command.ReportFound found) {
            reportFound(r, found.object(), current);
        } else if (e instanceof Command.ReportMetric metric) {
            reportMetric(r.name, metric, current);
        } else if (e instanceof Command.EndRun end) {
            if (endRequest == null) {
                endRequest = new Snapshot.EndRequest(r.name, current, end.reason());
            }
        } else {
            throw new IllegalStateException("no handler for the run event " + e);
        }
    }

    private void reportFound(SimRobot r, String object, long current) {
        HeatSource gold = world.gold();
        if (!"gold".equals(object) || gold == null) {
            messages.error(r.name, "robot " + r.name + " reported finding '" + object + "', but world "
                    + world.name() + " has no " + object);
            return;
        }
        double d = Math.hypot(r.x() - gold.x(), r.y() - gold.y());
        if (d > Simulation.GOLD_FOUND_DISTANCE) {
            messages.error(r.name, "robot " + r.name + " reported the gold at step " + current + " but is "
                    + Math.round(d) + " mm from it; a find counts within " + Math.round(Simulation.GOLD_FOUND_DISTANCE)
                    + " mm");
        } else if (find == null) {
            find = new Find(r.name, current, d);
        }
    }

    private void reportMetric(String robot, Command.ReportMetric m, long current) {
        Map<String, Double> own = metrics.computeIfAbsent(robot, k -> new LinkedHashMap<>());
        if (!own.containsKey(m.name()) && own.size() >= Command.ReportMetric.MAX_METRICS) {
            messages.error(robot, "step " + current + ": robot " + robot + " has reported " + own.size()
                    + " metrics, the most a robot may report; metric " + m.name() + " was not kept");
            return;
        }
        own.put(m.name(), m.value());
        reported.put(robot + '\n' + m.name(), new Snapshot.Metric(robot, m.name(), m.value()));
    }

    /** @return what robots said in the last step, in order */
    List<Snapshot.Said> said() {
        return said;
    }

    /** @return the first confirmed find of the gold, or null */
    Find find() {
        return find;
    }

    /** @return the metrics reported in the last step, in the order they were first reported in it */
    List<Snapshot.Metric> reported() {
        return List.copyOf(reported.values());
    }

    /**
     * @param robot a robot
     * @return the last value of each metric it reported, in the order it first reported them; empty if none
     */
    Map<String, Double> metrics(String robot) {
        return metrics.getOrDefault(robot, Map.of());
    }

    /** @return the first request to end the run, or null */
    Snapshot.EndRequest endRequest() {
        return endRequest;
    }
}
