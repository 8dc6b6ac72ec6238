package robosim.protocol;

import java.util.Locale;
import java.util.Map;
import java.util.TreeSet;

/**
 * Colours as world files and ACTS channel bindings name them: one of {@link #NAMES}, or
 * {@code #rrggbb} in hexadecimal. A colour is held as its 24-bit RGB value.
 */
public final class Colors {
    /** The named colours, by their lower-case names. */
    public static final Map<String, Integer> NAMES = Map.ofEntries(
            Map.entry("red", 0xff0000), Map.entry("green", 0x00ff00), Map.entry("blue", 0x0000ff),
            Map.entry("yellow", 0xffff00), Map.entry("cyan", 0x00ffff), Map.entry("magenta", 0xff00ff),
            Map.entry("orange", 0xffa500), Map.entry("purple", 0x800080), Map.entry("white", 0xffffff),
            Map.entry("black", 0x000000), Map.entry("gray", 0x808080), Map.entry("brown", 0xa52a2a),
            Map.entry("pink", 0xffc0cb));

    private Colors() {
    }

    /**
     * @param text a colour's name or {@code #rrggbb}, case ignored, blanks around it trimmed
     * @return its RGB value
     * @throws IllegalArgumentException naming the value and the rule, if it is neither
     */
    public static int parse(String text) {
        if (text == null) {
            throw new IllegalArgumentException("a colour is missing: give a name such as red or #rrggbb");
        }
        String t = text.trim().toLowerCase(Locale.ROOT);
        Integer named = NAMES.get(t);
        if (named != null) {
            return named;
        }
        if (t.matches("#[0-9a-f]{6}")) {
            return Integer.parseInt(t.substring(1), 16);
        }
        throw new IllegalArgumentException("'" + text + "' is not a colour: give #rrggbb or one of "
                + String.join(", ", new TreeSet<>(NAMES.keySet())));
    }

    /**
     * @param rgb an RGB value
     * @return it as {@code #rrggbb}
     */
    public static String format(int rgb) {
        return String.format("#%06x", rgb & 0xffffff);
    }
}
