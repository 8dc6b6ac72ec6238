package robosim.remote;

import java.util.Locale;

/**
 * Checks what is typed in the move-distance and heading fields before anything is sent; an error
 * names the field, the bad value and the rule.
 */
public final class DriveFields {
    /** The longest move the field takes, mm: further than any shipped world is wide. */
    public static final double MAX_DISTANCE = 100_000;

    private DriveFields() {
    }

    /**
     * @param text what the move-distance field holds
     * @return the distance, mm
     * @throws IllegalArgumentException naming the value and the rule
     */
    public static double distance(String text) {
        double d = number("move distance", text, "a distance in mm, e.g. 500, or -250 to back up");
        if (d == 0 || Math.abs(d) > MAX_DISTANCE) {
            throw new IllegalArgumentException("'" + text.trim() + "' was supplied for move distance: it is from "
                    + fmt(-MAX_DISTANCE) + " to " + fmt(MAX_DISTANCE) + " mm, and not 0");
        }
        return d;
    }

    /**
     * @param text what the heading field holds
     * @return the heading, degrees in [-180, 180]
     * @throws IllegalArgumentException naming the value and the rule
     */
    public static double heading(String text) {
        double h = number("heading", text, "a heading in degrees, e.g. 90 (counter-clockwise from the x axis)");
        if (h < -180 || h > 180) {
            throw new IllegalArgumentException("'" + text.trim() + "' was supplied for heading: a heading is -180 to 180"
                    + " degrees, counter-clockwise from the x axis");
        }
        return h;
    }

    private static double number(String field, String text, String rule) {
        String t = text == null ? "" : text.trim();
        double v;
        try {
            v = Double.parseDouble(t);
        } catch (NumberFormatException e) {
            v = Double.NaN;
        }
        // parseDouble takes "NaN", "Infinity" and hex floats; a field takes plain decimals only
        if (!t.matches("[-+]?(\\d+(\\.\\d*)?|\\.\\d+)") || !Double.isFinite(v)) {
            throw new IllegalArgumentException("'" + t + "' was supplied for " + field + ": it is " + rule);
        }
        return v;
    }

    private static String fmt(double v) {
        return String.format(Locale.ROOT, "%.0f", v);
    }
}
