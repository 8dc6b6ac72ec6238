package robosim.panel.model;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import robosim.protocol.RunStatus;

/**
 * What the panel's robot table shows: one row per robot of a {@link RunStatus}, every cell text
 * as the user reads it (mm and degrees rounded, counts as they are).
 */
public final class RobotRows {
    /** The columns' headings, in order. */
    public static final List<String> COLUMNS = List.of("Name", "Type", "Driven by", "Pose (x, y, th)",
            "Velocity (mm/s, deg/s)", "Stalled", "Collisions", "Sent", "Received", "Last step", "Connection");
    /** The column of the robot's name. */
    public static final int NAME = 0;
    /** The column of the connection state. */
    public static final int CONNECTION = COLUMNS.size() - 1;

    private RobotRows() {
    }

    /**
     * @param status the run's status
     * @return a row of {@link #COLUMNS} per robot, in the status's order
     */
    public static List<List<String>> of(RunStatus status) {
        return of(status, Set.of());
    }

    /**
     * @param status the run's status
     * @param seen   the robots seen connected in this run so far (see {@link SeenRobots})
     * @return a row of {@link #COLUMNS} per robot, in the status's order
     */
    public static List<List<String>> of(RunStatus status, Set<String> seen) {
        List<List<String>> rows = new ArrayList<>();
        for (RunStatus.RobotStatus r : status.robots()) {
            rows.add(List.of(r.name(), r.type(), r.drivenBy().isEmpty() ? "-" : r.drivenBy(),
                    String.format(Locale.ROOT, "%.0f, %.0f, %.0f", r.x(), r.y(), r.th()),
                    String.format(Locale.ROOT, "%.0f, %.1f", r.vel(), r.rotVel()),
                    r.stalled() ? "stalled" : "no", Long.toString(r.collisions()), Long.toString(r.sent()),
                    Long.toString(r.received()), Long.toString(r.lastStep()), connection(r, status, seen)));
        }
        return rows;
    }

    /**
     * @return the robot's connection as a user asks about it: is its program there, and is it keeping
     *         up; a robot not connected has "gone" only if it was ever there (it answered a step, or the
     *         panel saw it connected), else it is "not connected yet", as a robot of an open world that
     *         never joined
     */
    static String connection(RunStatus.RobotStatus r, RunStatus status, Set<String> seen) {
        if (r.connected()) {
            return status.step() > 0 && r.lastStep() < status.step() ? "connected, behind" : "connected";
        }
        return r.lastStep() > 0 || seen.contains(r.name()) ? "gone" : "not connected yet";
    }

    /**
     * @param status the run's status
     * @return the run in one line: world, step, simulated time, running or paused, and pace
     */
    public static String runLine(RunStatus status) {
        String pace = status.pace() == 0 ? "max" : status.pace() == 1 ? "real time"
                : String.format(Locale.ROOT, "%sx real time", status.pace());
        long connected = status.robots().stream().filter(RunStatus.RobotStatus::connected).count();
        return String.format(Locale.ROOT, "world %s - step %d (%.1f s) - %s - pace %s - %d of %d robots connected",
                status.world(), status.step(), status.timeMs() / 1000.0, status.paused() ? "paused" : "running", pace,
                connected, status.robots().size());
    }
}
