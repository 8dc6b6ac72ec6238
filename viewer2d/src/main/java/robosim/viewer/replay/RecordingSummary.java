package robosim.viewer.replay;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.RecordingException;
import robosim.protocol.recording.RecordingReader;

/**
 * A recording summed up, for {@code robosim replay --info}: the world, the steps, and per robot
 * the distance travelled (the sum of the straight lines between its true positions step to step,
 * so a little under the arc length the Environment reports for curved motion) and its collisions
 * (the steps at which it became stalled).
 *
 * @param world     the world's name
 * @param width     world width, mm
 * @param height    world height, mm
 * @param stepMs    step length, ms
 * @param obstacles how many walls and obstacles it has
 * @param snapshots    how many snapshots the recording holds (read whole)
 * @param firstStep the first snapshot's step, or -1
 * @param lastStep  the last snapshot's step, or -1
 * @param timeMs    simulated time at the last snapshot, ms
 * @param messages  messages the robots sent
 * @param said      things the robots said
 * @param robots    per robot, in the world's order then in order of appearance
 * @param sensors   whether the recording keeps sonar and laser readings
 * @param endReason why the run ended, or {@code null} if the recording has no end record
 * @param problem   the damage that stopped the reading, or {@code null}
 * @param events    the robots that joined the run under way or went from it, in order
 * @param metrics   the metrics the robots reported, the last value of each: robot to name to value,
 *                  robots and names in the order they were first reported; empty for a recording
 *                  made before robots reported them
 * @param endRequest the robot's request that ended the run, or {@code null} if none did
 */
public record RecordingSummary(String world, double width, double height, int stepMs, int obstacles, long snapshots,
                               long firstStep, long lastStep, long timeMs, long messages, long said,
                               List<RobotTotals> robots, boolean sensors, String endReason,
                               RecordingException problem, List<Snapshot.Event> events,
                               Map<String, Map<String, Double>> metrics, Snapshot.EndRequest endRequest) {
    /** Copies the lists and maps so the record stays immutable, and in order. */
    public RecordingSummary {
        robots = List.copyOf(robots);
        events = List.copyOf(events);
        Map<String, Map<String, Double>> copy = new LinkedHashMap<>();
        metrics.forEach((robot, own) -> copy.put(robot, Collections.unmodifiableMap(new LinkedHashMap<>(own))));
        metrics = Collections.unmodifiableMap(copy);
    }

    /**
     * One robot's totals.
     *
     * @param name       its name
     * @param type       its type, from the world ({@code ?} if the world does not list it)
     * @param distance   mm travelled, from its true positions
     * @param collisions how many times it became stalled
     * @param x          its last true x, mm
     * @param y          its last true y, mm
     * @param th         its last true heading, degrees
     */
    public record RobotTotals(String name, String type, double distance, long collisions, double x, double y,
                              double th) { }

    /** A robot's running totals. */
    private static final class Tally {
        String type;
        RobotView last;
        double distance;
        long collisions;

        Tally(String type) {
            this.type = type;
        }
    }

    /**
     * Reads a recording to its end (or its damage) and sums it up.
     *
     * @param reader an open recording, positioned after its world
     * @return the summary
     * @throws IOException if the file cannot be read
     */
    public static RecordingSummary of(RecordingReader reader) throws IOException {
        WorldDescription world = reader.world();
        Map<String, Tally> tallies = new LinkedHashMap<>();
        world.robots().forEach(r -> tallies.put(r.name(), new Tally(r.robotType())));
        long snapshots = 0;
        long first = -1;
        long last = -1;
        long time = 0;
        long messages = 0;
        long said = 0;
        RecordingException problem = null;
        List<Snapshot.Event> events = new ArrayList<>();
        Map<String, Map<String, Double>> metrics = new LinkedHashMap<>();
        Snapshot.EndRequest endRequest = null;
        try {
            Snapshot f;
            while ((f = reader.next()) != null) {
                // a robot that joined an open world is in the world sent again before its first snapshot
                reader.world().robots().forEach(r -> tallies.computeIfAbsent(r.name(), n -> new Tally("?")).type =
                        r.robotType());
                events.addAll(f.events());
                snapshots++;
                first = first < 0 ? f.step() : first;
                last = f.step();
                time = f.timeMs();
                messages += f.messages().size();
                said += f.said().size();
                for (Snapshot.Metric m : f.metrics()) {
                    metrics.computeIfAbsent(m.robot(), r -> new LinkedHashMap<>()).put(m.name(), m.value());
                }
                if (f.endRequest() != null && endRequest == null) {
                    endRequest = f.endRequest();
                }
                for (RobotView r : f.robots()) {
                    add(tallies.computeIfAbsent(r.name(), n -> new Tally("?")), r);
                }
            }
        } catch (RecordingException e) {
            problem = e;
        }
        List<RobotTotals> robots = new ArrayList<>();
        tallies.forEach((name, t) -> robots.add(new RobotTotals(name, t.type, t.distance, t.collisions,
                t.last == null ? Double.NaN : t.last.x(), t.last == null ? Double.NaN : t.last.y(),
                t.last == null ? Double.NaN : t.last.th())));
        return new RecordingSummary(world.name(), world.width(), world.height(), world.stepMs(),
                world.obstacles().size(), snapshots, first, last, time, messages, said, robots, reader.sensors(),
                reader.endReason(), problem, events, metrics, endRequest);
    }

    private static void add(Tally t, RobotView r) {
        if (t.last != null) {
            double d = Math.hypot(r.x() - t.last.x(), r.y() - t.last.y());
            if (Double.isFinite(d)) {
                t.distance += d;
            }
            if (r.stalled() && !t.last.stalled()) {
                t.collisions++;
            }
        }
        t.last = r;
    }
}
