package robosim.params;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * A robot's bump rings, as ARIA's parameter files give them ({@code FrontBumpers},
 * {@code NumFrontBumpers}, {@code RearBumpers}, {@code NumRearBumpers}; ARIA's
 * {@code ArRobotParams.cpp}). A ring's bumpers share the stall value's byte with a motor's stall
 * bit (ARIA's {@code ArBumpers.cpp}), so a ring has at most {@value #MAX_BUMPERS} bumpers.
 *
 * @param frontBumpers    whether the robot has a front bump ring
 * @param numFrontBumpers how many bumpers the front ring has
 * @param rearBumpers     whether the robot has a rear bump ring
 * @param numRearBumpers  how many bumpers the rear ring has
 */
public record BumperParameters(boolean frontBumpers, int numFrontBumpers, boolean rearBumpers, int numRearBumpers) {
    /** The most bumpers a ring can have: bits 1 to 7 of its byte of the stall value. */
    public static final int MAX_BUMPERS = 7;

    /** ARIA's defaults ({@code ArRobotParams}' constructor): no rings, five bumpers each. */
    public static final BumperParameters ARIA_DEFAULTS = new BumperParameters(false, 5, false, 5);

    /**
     * @throws IllegalArgumentException if a ring's count is not 1 to {@value #MAX_BUMPERS}
     */
    public BumperParameters {
        requireCount("numFrontBumpers", numFrontBumpers);
        requireCount("numRearBumpers", numRearBumpers);
    }

    private static void requireCount(String name, int count) {
        String rule = rule(count);
        if (rule != null) {
            throw new IllegalArgumentException(count + " was supplied for " + name + ": " + rule);
        }
    }

    private static String rule(int count) {
        return count < 1 || count > MAX_BUMPERS ? "a bump ring has 1 to " + MAX_BUMPERS + " bumpers" : null;
    }

    /**
     * Reads the bumper keys of an ARIA file's lines; a key it does not give keeps ARIA's default, and
     * a key given twice keeps its last value.
     *
     * @param file  the file, for messages
     * @param lines its lines
     * @return the bump rings
     * @throws ParameterFileException naming the file, the line and the rule for a bad value
     */
    static BumperParameters read(Path file, List<String> lines) {
        boolean front = ARIA_DEFAULTS.frontBumpers;
        boolean rear = ARIA_DEFAULTS.rearBumpers;
        int numFront = ARIA_DEFAULTS.numFrontBumpers;
        int numRear = ARIA_DEFAULTS.numRearBumpers;
        for (int i = 0; i < lines.size(); i++) {
            String[] words = ParameterFileReader.stripComment(lines.get(i)).trim().split("\\s+");
            String key = words[0].toLowerCase(Locale.ROOT);
            switch (key) {
                case "frontbumpers" -> front = flag(file, i + 1, words);
                case "rearbumpers" -> rear = flag(file, i + 1, words);
                case "numfrontbumpers" -> numFront = count(file, i + 1, words);
                case "numrearbumpers" -> numRear = count(file, i + 1, words);
                default -> {
                }
            }
        }
        return new BumperParameters(front, numFront, rear, numRear);
    }

    /** ARIA's boolean values: true/false, also 1/0, without regard to case. */
    private static boolean flag(Path file, int line, String[] words) {
        String v = value(file, line, words).toLowerCase(Locale.ROOT);
        return switch (v) {
            case "true", "1" -> true;
            case "false", "0" -> false;
            default -> throw new ParameterFileException(file, line,
                    words[0] + " " + ParameterRules.quote(words[1]) + " is not a boolean: it is true or false");
        };
    }

    private static int count(Path file, int line, String[] words) {
        String v = value(file, line, words);
        int n;
        try {
            n = Integer.parseInt(v);
        } catch (NumberFormatException e) {
            throw new ParameterFileException(file, line, words[0] + " " + ParameterRules.quote(v)
                    + " is not a whole number");
        }
        String rule = rule(n);
        if (rule != null) {
            throw new ParameterFileException(file, line, words[0] + " is " + v + " but " + rule);
        }
        return n;
    }

    private static String value(Path file, int line, String[] words) {
        if (words.length < 2) {
            throw new ParameterFileException(file, line, words[0] + " has no value");
        }
        return words[1];
    }
}
