package robosim.env.world.xml;

import java.nio.file.Path;
import java.util.regex.Pattern;
import robosim.env.world.World;
import robosim.protocol.LogLimiter;

/**
 * Checks and converts attribute text for one world file, reporting each broken rule with the
 * file, the element's line, the attribute and the value, the value quoted as an excerpt
 * ({@link #quote(String)}) so that no file can fill a terminal or write to it.
 */
final class Attributes {
    /** The largest number a world file may hold either way: 1000 km in mm, ten times the largest world. */
    static final double MAX_MAGNITUDE = 1e9;
    /** The longest name a world may have. */
    static final int MAX_NAME = 200;

    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?");

    private final Path file;

    Attributes(Path file) {
        this.file = file;
    }

    /** @return the world file the attributes come from */
    Path file() {
        return file;
    }

    /**
     * @param text text from the file, or null
     * @return it as an error quotes it: in single quotes, escaped and cut short (see {@link LogLimiter#excerpt})
     */
    static String quote(String text) {
        return "'" + LogLimiter.excerpt(text) + "'";
    }

    WorldFileException error(Element element, String rule) {
        return new WorldFileException(file, element.line(), rule);
    }

    /**
     * @return the value as a name shown in logs and viewers: trimmed, present, at most
     *         {@link #MAX_NAME} characters and none a control character
     */
    String name(Element element, String attribute, String value) {
        String text = text(element, attribute, value);
        if (text.length() > MAX_NAME || text.chars().anyMatch(Character::isISOControl)) {
            throw error(element, "attribute " + attribute + " on <" + element.tag() + "> is " + quote(text)
                    + " but a name is at most " + MAX_NAME + " characters, none of them a control character");
        }
        return text;
    }

    /** @return the value, trimmed; it must be present and not blank */
    String text(Element element, String attribute, String value) {
        if (value == null) {
            throw error(element, "missing required attribute " + attribute + " on <" + element.tag() + ">");
        }
        String text = value.trim();
        if (text.isEmpty()) {
            throw error(element, "attribute " + attribute + " on <" + element.tag() + "> is empty");
        }
        return text;
    }

    /**
     * @return the value as a finite number of at most {@link #MAX_MAGNITUDE} either way (1000 km in
     *         mm: ten times the largest world); it must be present
     */
    double number(Element element, String attribute, String value) {
        String text = text(element, attribute, value);
        if (!NUMBER.matcher(text).matches() || !Double.isFinite(Double.parseDouble(text))) {
            throw error(element, "attribute " + attribute + " on <" + element.tag() + "> is " + quote(text)
                    + ", not a number");
        }
        double v = Double.parseDouble(text);
        if (Math.abs(v) > MAX_MAGNITUDE) {
            throw error(element, "attribute " + attribute + " on <" + element.tag() + "> is "
                    + LogLimiter.excerpt(text)
                    + " but must be from " + format(-MAX_MAGNITUDE) + " to " + format(MAX_MAGNITUDE)
                    + ": no number in a world file is larger");
        }
        return v;
    }

    /** @return the value as a finite number, or {@code fallback} when it is absent */
    double number(Element element, String attribute, String value, double fallback) {
        return value == null ? fallback : number(element, attribute, value);
    }

    /**
     * @return the value as a coordinate, a number from -{@link World#MAX_SIZE} to {@link World#MAX_SIZE};
     *         it must be present (a single number of a list, such as a polygon's points, is named by the list)
     */
    double coordinate(Element element, String attribute, String value) {
        double v = number(element, attribute, value);
        if (Math.abs(v) > World.MAX_SIZE) {
            throw error(element, "attribute " + attribute + " on <" + element.tag() + "> holds " + format(v)
                    + " but a coordinate must be from " + format(-World.MAX_SIZE) + " to " + format(World.MAX_SIZE));
        }
        return v;
    }

    /** @return the value as a number greater than 0; it must be present */
    double positive(Element element, String attribute, String value) {
        return checkPositive(element, attribute, number(element, attribute, value));
    }

    /** @return the value, if it is at most {@code max} */
    double atMost(Element element, String attribute, double value, double max) {
        if (value > max) {
            throw error(element, "attribute " + attribute + " on <" + element.tag() + "> is " + format(value)
                    + " but must be at most " + format(max));
        }
        return value;
    }

    /** @return the value as a number greater than 0, or {@code fallback} when it is absent */
    double positive(Element element, String attribute, String value, double fallback) {
        return value == null ? fallback : positive(element, attribute, value);
    }

    /** @return the value as a number 0 or greater, or {@code fallback} when it is absent */
    double nonNegative(Element element, String attribute, String value, double fallback) {
        if (value == null) {
            return fallback;
        }
        double v = number(element, attribute, value);
        if (v < 0) {
            throw error(element, "attribute " + attribute + " on <" + element.tag() + "> is " + format(v)
                    + " but must be 0 or greater");
        }
        return v == 0 ? 0 : v; // -0 reads as 0, so that equal worlds compare equal
    }

    private double checkPositive(Element element, String attribute, double v) {
        if (v <= 0) {
            throw error(element, "attribute " + attribute + " on <" + element.tag() + "> is " + format(v)
                    + " but must be greater than 0");
        }
        return v;
    }

    /** @return the value as a whole number from {@code min} to {@code max}, or {@code fallback} when absent */
    int wholeNumber(Element element, String attribute, String value, int fallback, int min, int max) {
        if (value == null) {
            return fallback;
        }
        double v = number(element, attribute, value);
        if (v != Math.rint(v) || v < min || v > max) {
            throw error(element, "attribute " + attribute + " on <" + element.tag() + "> is " + format(v)
                    + " but must be a whole number from " + min + " to " + max);
        }
        return (int) v;
    }

    /**
     * @return the value as a whole number {@code min} or greater (and at most
     *         {@link Integer#MAX_VALUE}), or {@code fallback} when absent
     */
    int wholeNumber(Element element, String attribute, String value, int fallback, int min) {
        if (value == null) {
            return fallback;
        }
        double v = number(element, attribute, value);
        if (v != Math.rint(v) || v < min) {
            throw error(element, "attribute " + attribute + " on <" + element.tag() + "> is " + format(v)
                    + " but must be a whole number, " + min + " or greater");
        }
        return wholeNumber(element, attribute, value, fallback, min, Integer.MAX_VALUE);
    }

    /** @return the value as a number from {@code min} to {@code max}, or {@code fallback} when absent */
    double between(Element element, String attribute, String value, double fallback, double min, double max) {
        if (value == null) {
            return fallback;
        }
        double v = number(element, attribute, value);
        if (v < min || v > max) {
            throw error(element, "attribute " + attribute + " on <" + element.tag() + "> is " + format(v)
                    + " but must be from " + format(min) + " to " + format(max));
        }
        return v == 0 ? 0 : v; // -0 reads as 0, so that equal worlds compare equal
    }

    /** @return the value as {@code true} or {@code false}, or {@code fallback} when it is absent */
    boolean bool(Element element, String attribute, String value, boolean fallback) {
        if (value == null) {
            return fallback;
        }
        String text = value.trim();
        if (!text.equals("true") && !text.equals("false")) {
            throw error(element, "attribute " + attribute + " on <" + element.tag() + "> is " + quote(text)
                    + " but must be true or false");
        }
        return Boolean.parseBoolean(text);
    }

    /** @return the number without a trailing {@code .0} when it is whole, for messages */
    static String format(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}
