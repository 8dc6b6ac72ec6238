package robosim.env.net;

import java.util.List;
import java.util.Locale;
import robosim.env.core.Simulation;
import robosim.env.world.World;
import robosim.protocol.ControlRequest;
import robosim.protocol.RobotHello;

/**
 * A control client's request, read and checked: every value within its rule before anything in the
 * run changes. {@link #parse} names the operation, the bad value and the rule when it refuses.
 */
sealed interface ControlOp {
    /** The most steps one {@code step N} runs. */
    long MAX_STEPS = 1_000_000;
    /** The slowest pace, as a factor of real time. */
    double MIN_PACE = 0.01;
    /** The fastest pace other than {@code max}, as a factor of real time. */
    double MAX_PACE = 1000;
    /** The farthest from the origin a robot may be moved, mm: the world file's coordinate bound. */
    double MAX_COORDINATE = 1e8;
    /** The largest heading a move accepts, degrees (any angle is folded into -180..180). */
    double MAX_HEADING = 1e6;

    /** Stop running steps after the one under way. */
    record Pause() implements ControlOp { }

    /** Run steps again. */
    record Resume() implements ControlOp { }

    /** While paused, run this many steps, then pause again. */
    record Step(long steps) implements ControlOp { }

    /** End the run cleanly. */
    record Stop() implements ControlOp { }

    /** Pace the steps: 0 for as fast as possible, else a factor of real time. */
    record Pace(double factor) implements ControlOp { }

    /** Place a robot at a true pose, its odometry unchanged. */
    record Move(String robot, double x, double y, double th) implements ControlOp { }

    /** Take a robot out of the run. */
    record Remove(String robot) implements ControlOp { }

    /** Run the same world again from step 0, with the same seed. */
    record Restart() implements ControlOp { }

    /**
     * Run another world from step 0, with the same seed.
     *
     * @param path  the world file as the client named it
     * @param world the world read and checked, or null until {@link WorldLoader} has read it
     */
    record Load(String path, World world) implements ControlOp { }

    /**
     * @param r   the request
     * @param sim the run's simulation, for the robots' names
     * @return the operation it asks for
     * @throws IllegalArgumentException naming the operation, the bad value and the rule
     */
    static ControlOp parse(ControlRequest r, Simulation sim) {
        checkCount(r);
        String op = r.op() == null ? "" : r.op();
        List<String> a = r.args();
        return switch (op) {
            case "pause" -> new Pause();
            case "resume" -> new Resume();
            case "stop" -> new Stop();
            case "restart" -> new Restart();
            case "load" -> new Load(a.get(0), null);
            case "step" -> new Step(steps(a.get(0)));
            case "pace" -> new Pace(pace(a.get(0)));
            case "remove" -> new Remove(robot(op, a.get(0), sim));
            case "move" -> new Move(robot(op, a.get(0), sim), coordinate("X", a.get(1)),
                    coordinate("Y", a.get(2)), heading(a.get(3)));
            default -> throw new IllegalArgumentException("unknown operation '" + RobotHello.printable(op, 40)
                    + "'; the operations are pause, resume, step N, stop, pace max|realtime|K, move NAME X Y TH,"
                    + " remove NAME, restart, load WORLD, status, log");
        };
    }

    /** Checks the count of arguments before any is read, so a short request names the rule, not an index. */
    private static void checkCount(ControlRequest r) {
        int n = switch (r.op() == null ? "" : r.op()) {
            case "pause", "resume", "stop", "restart" -> 0;
            case "step", "pace", "remove", "load" -> 1;
            case "move" -> 4;
            default -> -1;
        };
        if (n >= 0 && r.args().size() != n) {
            throw new IllegalArgumentException(r.op() + " takes " + n + " argument" + (n == 1 ? "" : "s") + " ("
                    + usage(r.op()) + "), got " + r.args().size());
        }
    }

    private static String usage(String op) {
        return switch (op) {
            case "step" -> "step N";
            case "pace" -> "pace max|realtime|K";
            case "remove" -> "remove NAME";
            case "load" -> "load WORLD";
            case "move" -> "move NAME X Y TH";
            default -> op;
        };
    }

    private static long steps(String text) {
        long n;
        try {
            n = Long.parseLong(text.trim());
        } catch (NumberFormatException e) {
            n = 0;
        }
        if (n < 1 || n > MAX_STEPS) {
            throw new IllegalArgumentException("step N: N is a whole number from 1 to " + MAX_STEPS + ", got '"
                    + RobotHello.printable(text, 40) + "'");
        }
        return n;
    }

    private static double pace(String text) {
        String t = text.trim().toLowerCase(Locale.ROOT);
        if (t.equals("max")) {
            return 0;
        }
        if (t.equals("realtime")) {
            return 1;
        }
        double k = number(t);
        if (!(k >= MIN_PACE && k <= MAX_PACE)) {
            throw new IllegalArgumentException("pace: the pace is max, realtime or a factor of real time from "
                    + MIN_PACE + " to " + (long) MAX_PACE + ", got '" + RobotHello.printable(text, 40) + "'");
        }
        return k;
    }

    private static String robot(String op, String name, Simulation sim) {
        if (!sim.robotNames().contains(name)) {
            throw new IllegalArgumentException(op + ": no robot named '" + RobotHello.printable(name, 40)
                    + "' in world " + sim.world().name());
        }
        return name;
    }

    private static double coordinate(String axis, String text) {
        double v = number(text);
        if (!(Math.abs(v) <= MAX_COORDINATE)) {
            throw new IllegalArgumentException("move: " + axis + " is a number of mm within " + (long) MAX_COORDINATE
                    + " of the origin, got '" + RobotHello.printable(text, 40) + "'");
        }
        return v;
    }

    private static double heading(String text) {
        double v = number(text);
        if (!(Math.abs(v) <= MAX_HEADING)) {
            throw new IllegalArgumentException("move: TH is a heading in degrees within " + (long) MAX_HEADING
                    + " of 0, got '" + RobotHello.printable(text, 40) + "'");
        }
        return v;
    }

    /** @return the number, or NaN when the text is not one (which every range check then refuses) */
    private static double number(String text) {
        try {
            return Double.parseDouble(text.trim());
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }
}
