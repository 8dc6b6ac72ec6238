package robosim.panel.model;

import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * A control request as a button of the panel sends it: the operation and its arguments, the words
 * {@code robosim control} would send. The factories check what the user typed and name the field,
 * the bad value and the rule, so that a mistake is shown at once instead of after a round trip.
 *
 * @param op   the operation
 * @param args its arguments
 */
public record Request(String op, List<String> args) {
    /** The most steps one step request runs, as the Environment allows. */
    public static final long MAX_STEPS = 1_000_000;
    /** The farthest from the origin a robot may be moved, mm, as the Environment allows. */
    public static final double MAX_COORDINATE = 1e8;

    /** Copies the arguments. */
    public Request {
        args = List.copyOf(args);
    }

    /** @return the request that pauses the run after the step under way */
    public static Request pause() {
        return new Request("pause", List.of());
    }

    /** @return the request that runs steps again */
    public static Request resume() {
        return new Request("resume", List.of());
    }

    /** @return the request that ends the run cleanly */
    public static Request stop() {
        return new Request("stop", List.of());
    }

    /**
     * @param text the number of steps the user typed
     * @return the request that runs that many steps while paused
     * @throws IllegalArgumentException if it is not a whole number from 1 to {@value #MAX_STEPS}
     */
    public static Request step(String text) {
        long n;
        try {
            n = Long.parseLong(text.trim());
        } catch (NumberFormatException e) {
            n = 0;
        }
        if (n < 1 || n > MAX_STEPS) {
            throw new IllegalArgumentException("Steps: a whole number from 1 to " + MAX_STEPS + ", got '" + text + "'");
        }
        return new Request("step", List.of(Long.toString(n)));
    }

    /**
     * @param pace a stop of {@link Pace}
     * @return the request that sets it
     */
    public static Request pace(Pace pace) {
        return new Request("pace", List.of(pace.word()));
    }

    /**
     * @param robot the robot's name
     * @param x     x, mm, as typed
     * @param y     y, mm, as typed
     * @param th    heading, degrees, as typed
     * @return the request that places the robot there, its odometry unchanged
     * @throws IllegalArgumentException naming the field that is not a number within its range
     */
    public static Request move(String robot, String x, String y, String th) {
        double[] v = {number("X", x, MAX_COORDINATE), number("Y", y, MAX_COORDINATE), number("TH", th, 1e6)};
        return new Request("move", List.of(robot, plain(v[0]), plain(v[1]), plain(v[2])));
    }

    /**
     * @param robot the robot's name
     * @return the request that takes it out of the run
     */
    public static Request remove(String robot) {
        return new Request("remove", List.of(robot));
    }

    /** @return the request that runs the world again from step 0 with the same seed */
    public static Request restart() {
        return new Request("restart", List.of());
    }

    /**
     * @param world the world file chosen: a file that exists here is sent as its absolute path (the
     *              Environment takes a relative path from its own world's directory, not from the
     *              panel's), any other as typed, for the Environment to find beside its world
     * @return the request that runs that world in place of the run's
     * @throws IllegalArgumentException if no world is chosen
     */
    public static Request load(String world) {
        String w = world == null ? "" : world.strip();
        if (w.isEmpty()) {
            throw new IllegalArgumentException("Load: choose or type a world file first");
        }
        Path p;
        try {
            p = Path.of(w);
        } catch (InvalidPathException e) {
            throw new IllegalArgumentException("Load: '" + w + "' is not a file name: " + e.getReason());
        }
        return new Request("load", List.of(Files.isRegularFile(p) ? p.toAbsolutePath().normalize().toString() : w));
    }

    /** @return the request as {@code robosim control} takes it, for the log */
    @Override
    public String toString() {
        return args.isEmpty() ? op : op + " " + String.join(" ", args);
    }

    private static double number(String field, String text, double bound) {
        double v;
        try {
            v = Double.parseDouble(text.trim());
        } catch (NumberFormatException e) {
            v = Double.NaN;
        }
        if (!(Math.abs(v) <= bound)) {
            throw new IllegalArgumentException(field + ": a number within " + (long) bound + " of 0, got '" + text + "'");
        }
        return v;
    }

    /** @return the number without a trailing ".0" or an exponent, as a user would type it */
    private static String plain(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : String.format(Locale.ROOT, "%s", v);
    }
}
