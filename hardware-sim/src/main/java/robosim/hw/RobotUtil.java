package robosim.hw;

import java.io.PrintStream;
import java.util.Locale;
import java.util.Objects;
import java.util.function.Consumer;
import java.util.logging.Logger;
import robosim.protocol.Bumpers;
import robosim.protocol.HeatReading;
import robosim.protocol.LaserReading;
import robosim.protocol.RobotState;
import robosim.protocol.SonarReading;
import robosim.protocol.TruePose;

/**
 * The original RoboSim's {@code RobotUtil}: controlled message output for a robot's program, and a
 * printable snapshot of the robot's state at any step.
 *
 * <p>Messages have ARIA's levels ({@code ArLog}: terse, normal, verbose); a message more detailed
 * than the chosen level is dropped. Each line starts with the robot's name, the step and the
 * simulated time, so the lines of several robots sort into one story:
 * {@code [r1 step 42 4.200 s] NORMAL: turning left}. Lines go to the logger
 * {@code robosim.robot.<name>} until {@link #setOutput} names a stream or a sink.
 *
 * <pre>{@code
 * RobotUtil out = new RobotUtil(robot);
 * out.setOutput(System.out);
 * out.normal("wall at %d mm", robot.getSonarRange(3));
 * out.verbose(RobotUtil.snapshot(robot));
 * }</pre>
 */
public final class RobotUtil {
    /** How much a message tells, as ARIA's {@code ArLog::LogLevel}: each level shows the ones before it. */
    public enum Level {
        /** What always matters: errors, the result. */
        TERSE,
        /** What a user follows while the program runs. */
        NORMAL,
        /** What a developer looks at to debug. */
        VERBOSE
    }

    private final AbstractRobot robot;
    private volatile Level level = Level.NORMAL;
    private volatile Consumer<String> sink;

    /**
     * Output for one robot, at {@link Level#NORMAL}, to the robot's logger.
     *
     * @param robot the robot whose name and step head each line
     */
    public RobotUtil(AbstractRobot robot) {
        this.robot = Objects.requireNonNull(robot, "robot");
        Logger logger = Logger.getLogger("robosim.robot." + robot.getName());
        this.sink = logger::info;
    }

    /** @param level the most detailed level shown */
    public void setLevel(Level level) {
        this.level = Objects.requireNonNull(level, "level");
    }

    /** @return the most detailed level shown */
    public Level getLevel() {
        return level;
    }

    /** @param out a stream each line is printed to */
    public void setOutput(PrintStream out) {
        Objects.requireNonNull(out, "out");
        setOutput(out::println);
    }

    /** @param lines where each line goes */
    public void setOutput(Consumer<String> lines) {
        sink = Objects.requireNonNull(lines, "lines");
    }

    /**
     * Writes a message if its level is shown.
     *
     * @param messageLevel how much the message tells
     * @param format       a {@link String#format} pattern (formatted in the root locale)
     * @param args         its arguments
     * @return whether the message was written
     */
    public boolean log(Level messageLevel, String format, Object... args) {
        if (messageLevel.compareTo(level) > 0) {
            return false;
        }
        String text = args.length == 0 ? format : String.format(Locale.ROOT, format, args);
        sink.accept(prefix() + " " + messageLevel + ": " + text);
        return true;
    }

    /** @param format a pattern @param args its arguments @return whether written */
    public boolean terse(String format, Object... args) {
        return log(Level.TERSE, format, args);
    }

    /** @param format a pattern @param args its arguments @return whether written */
    public boolean normal(String format, Object... args) {
        return log(Level.NORMAL, format, args);
    }

    /** @param format a pattern @param args its arguments @return whether written */
    public boolean verbose(String format, Object... args) {
        return log(Level.VERBOSE, format, args);
    }

    private String prefix() {
        RobotState s = robot.state();
        return String.format(Locale.ROOT, "[%s step %d %d.%03d s]", robot.getName(), s.step(), s.timeMs() / 1000,
                s.timeMs() % 1000);
    }

    /**
     * @param robot a robot
     * @return its latest state, printable (see {@link #snapshot(String, RobotState)}); before it
     *         connected, the empty state of step 0
     */
    public static String snapshot(AbstractRobot robot) {
        return snapshot(robot.getName(), robot.state());
    }

    /**
     * A robot's state as lines of text: step and time, odometry pose, velocities, stall, collisions
     * and bumper contacts, the sonar ranges (those not new in a sequenced ring marked with {@code *}),
     * the laser's scan summed up, the heat reading, the true pose when reported, messages and errors.
     *
     * @param name  the robot's name
     * @param state its state
     * @return the lines, joined by {@code \n}
     */
    public static String snapshot(String name, RobotState state) {
        RobotState s = Objects.requireNonNull(state, "state");
        StringBuilder b = new StringBuilder();
        line(b, "robot %s at step %d, %d.%03d s", name, s.step(), s.timeMs() / 1000, s.timeMs() % 1000);
        line(b, "  pose       x %.1f mm, y %.1f mm, th %.1f deg", s.x(), s.y(), s.th());
        line(b, "  velocity   %.1f mm/s, %.1f deg/s (left %.1f, right %.1f mm/s)", s.vel(), s.rotVel(), s.leftVel(),
                s.rightVel());
        line(b, "  contact    %s, %d collisions, bumper sectors %s", s.stalled() ? "stalled" : "not stalled",
                s.collisions(), sectors(s.get(Bumpers.PART).sectors()));
        line(b, "  sonar      %s", sonar(s));
        line(b, "  laser      %s", laser(s.get(LaserReading.PART).ranges()));
        HeatReading h = s.get(HeatReading.PART);
        line(b, "  heat       %s", h == null ? "off"
                : String.format(Locale.ROOT, "%.2f at %.1f deg, %.0f mm", h.intensity(), h.bearing(), h.distance()));
        TruePose t = s.get(TruePose.PART);
        line(b, "  true pose  %s", t == null ? "not reported"
                : String.format(Locale.ROOT, "x %.1f mm, y %.1f mm, th %.1f deg", t.x(), t.y(), t.th()));
        b.append(String.format(Locale.ROOT, "  messages   %d delivered, %d errors", s.messages().size(), s.errors().size()));
        for (String e : s.errors()) {
            b.append("\n    error: ").append(e);
        }
        return b.toString();
    }

    private static void line(StringBuilder b, String format, Object... args) {
        b.append(String.format(Locale.ROOT, format, args)).append('\n');
    }

    private static String sectors(int bumpers) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < Bumpers.SECTORS; i++) {
            if ((bumpers >> i & 1) != 0) {
                b.append(b.length() == 0 ? "" : ",").append(i);
            }
        }
        return b.length() == 0 ? "none" : b.toString();
    }

    private static String sonar(RobotState s) {
        SonarReading sonar = s.get(SonarReading.PART);
        int[] r = sonar.ranges();
        if (r == null || r.length == 0) {
            return "off";
        }
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < r.length; i++) {
            b.append(i == 0 ? "" : " ").append(r[i]).append(sonar.isNew(i) ? "" : "*");
        }
        return b.toString();
    }

    private static String laser(int[] scan) {
        if (scan == null || scan.length == 0) {
            return "off";
        }
        int nearest = 0;
        for (int i = 1; i < scan.length; i++) {
            if (scan[i] < scan[nearest]) {
                nearest = i;
            }
        }
        return String.format(Locale.ROOT, "%d readings, nearest %d mm at reading %d", scan.length, scan[nearest], nearest);
    }
}
