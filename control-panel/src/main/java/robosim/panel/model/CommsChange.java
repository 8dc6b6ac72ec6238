package robosim.panel.model;

import java.util.Locale;
import robosim.protocol.CommsUpdate;

/**
 * The panel's comms settings as typed: each field left empty keeps the setting in force. The
 * Environment checks the values again (and closes a connection that breaks a rule), so the checks
 * here are there to say what is wrong before anything is sent.
 */
public final class CommsChange {
    private CommsChange() {
    }

    /**
     * @param range      the farthest a message reaches, mm, 0 for no limit
     * @param wallsBlock "yes", "no", or empty to keep
     * @param latency    steps between sending and delivery, at least 1
     * @param loss       the chance a message is lost, 0 to 1
     * @param maxBytes   the largest payload, bytes, at least 1
     * @return the update to send
     * @throws IllegalArgumentException naming the field, the value and the rule, or when every field is empty
     */
    public static CommsUpdate parse(String range, String wallsBlock, String latency, String loss, String maxBytes) {
        Double r = number("Range", range, 0, 1e9);
        Double l = number("Loss", loss, 0, 1);
        Double lat = number("Latency", latency, 1, 1_000_000);
        Double max = number("Max bytes", maxBytes, 1, Integer.MAX_VALUE);
        Boolean walls = switch (wallsBlock == null ? "" : wallsBlock.trim().toLowerCase(Locale.ROOT)) {
            case "" -> null;
            case "yes" -> true;
            case "no" -> false;
            default -> throw new IllegalArgumentException("Walls block: yes, no or empty (keep), got '" + wallsBlock + "'");
        };
        if (lat != null && lat != Math.rint(lat) || max != null && max != Math.rint(max)) {
            throw new IllegalArgumentException((lat != null && lat != Math.rint(lat) ? "Latency" : "Max bytes")
                    + ": a whole number, got '" + (lat != null && lat != Math.rint(lat) ? latency : maxBytes) + "'");
        }
        if (r == null && l == null && lat == null && max == null && walls == null) {
            throw new IllegalArgumentException("Comms: give at least one setting to change");
        }
        return new CommsUpdate(r, walls, lat == null ? null : lat.intValue(), l, max == null ? null : max.intValue());
    }

    /**
     * @param now the settings the Environment confirmed
     * @return them in one line
     */
    public static String describe(CommsUpdate now) {
        return String.format(Locale.ROOT, "range %.0f mm, walls block %s, latency %d, loss %.3f, max %d bytes",
                now.maxRange(), now.wallsBlock(), now.latencySteps(), now.lossProbability(), now.maxMessageBytes());
    }

    private static Double number(String field, String text, double min, double max) {
        if (text == null || text.isBlank()) {
            return null;
        }
        double v;
        try {
            v = Double.parseDouble(text.trim());
        } catch (NumberFormatException e) {
            v = Double.NaN;
        }
        if (!(v >= min && v <= max)) {
            throw new IllegalArgumentException(field + ": a number from " + plain(min) + " to " + plain(max) + ", got '"
                    + text + "'");
        }
        return v;
    }

    private static String plain(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }
}
