package robosim.params;

import robosim.protocol.RobotParameters;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CoderResult;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.regex.Pattern;

/**
 * Reads ARIA's robot parameter files ({@code .p}): {@code ConfigVersion 2.0}, section headers
 * ({@code Section name} or {@code [name]}) and {@code Key value ; comment} lines. Keys are matched
 * without regard to case, as ARIA does; ARIA's keys RoboSim does not model ({@link AriaKeys}:
 * conversion factors, IO settings, the laser's port and flags, sonar boards, ...) are read past, and
 * keys nobody defines are named in one warning per file, so that ARIA's own files load unchanged.
 *
 * <p>A key that is absent keeps the default of ARIA's {@code ArRobotParams}, and so does an
 * acceleration or speed limit of 0, ARIA's "keep the firmware's value". A body length given
 * without {@code RobotLengthFront}/{@code RobotLengthRear} is split evenly about the centre. A
 * {@code SonarUnit} line gives its pose in its first four values; the MTX values after them are
 * ignored. The keys of a sonar board's section ({@code SonarBoard_1}, ...) describe the board, and
 * the laser keys of a later laser's section ({@code Laser 2 parameters}, ...) are ignored. The laser's
 * mounting pose comes from {@code LaserX}, {@code LaserY}, {@code LaserTh} and its range from
 * {@code LaserMaxRange} (default {@link RobotParameters#DEFAULT_LASER_MAX_RANGE}; ARIA's {@code 0}
 * also means the default). {@code HasGripper true} (RoboSim's own key; ARIA's files have none, and
 * a Pioneer's gripper is an accessory, so the default is none) mounts a Pioneer 2-DOF gripper.
 * {@link #conversionFactors} reads the file's conversion factors.
 *
 * <p>{@link XmlParameterFileReader} reads the same parameters from XML under the same rules;
 * {@link RobotParametersReader} picks one by extension.
 */
public final class ParameterFileReader {
    /** ARIA 2.8 repeats the laser keys in a section per laser; RoboSim models the first laser only. */
    private static final Pattern LATER_LASER =
            Pattern.compile("laser\\s+([2-9]|\\d{2,})\\s+parameters", Pattern.CASE_INSENSITIVE);

    /** The longest {@code SonarCycle}, ms (the Environment's bound). */
    public static final int MAX_SONAR_CYCLE_MS = 10_000;
    /**
     * The longest content a line may have before its comment: ARIA's own lines hold a few dozen
     * characters, and ARIA reads at most 10 000 of a line.
     */
    static final int MAX_LINE_CHARS = 4000;

    private ParameterFileReader() {
    }

    /**
     * Reads a parameter file.
     *
     * @param file the {@code .p} file
     * @return the robot's parameters
     * @throws ParameterFileException naming the file, the line and the rule when the file is broken
     * @throws UncheckedIOException   when the file cannot be read
     */
    public static RobotParameters read(Path file) {
        return parse(file, lines(file));
    }

    /**
     * Reads the conversion factors of a parameter file ({@code Section Conversion factors});
     * a factor the file does not give keeps {@link ConversionFactors#ARIA_DEFAULTS}' value.
     *
     * @param file the {@code .p} file
     * @return its conversion factors
     * @throws ParameterFileException naming the file, the line and the rule when a factor is not a
     *                                number greater than 0
     * @throws UncheckedIOException   when the file cannot be read
     */
    public static ConversionFactors conversionFactors(Path file) {
        return ConversionFactors.read(file, lines(file));
    }

    /**
     * Reads the bump rings of a parameter file ({@code FrontBumpers}, {@code NumFrontBumpers},
     * {@code RearBumpers}, {@code NumRearBumpers}); a key the file does not give keeps
     * {@link BumperParameters#ARIA_DEFAULTS}' value.
     *
     * @param file the {@code .p} file
     * @return its bump rings
     * @throws ParameterFileException naming the file, the line and the rule for a bad value
     * @throws UncheckedIOException   when the file cannot be read
     */
    public static BumperParameters bumpers(Path file) {
        return BumperParameters.read(file, lines(file));
    }

    /**
     * Reads RoboSim's {@code SonarCycle} key: the simulated ms between firings of the sonar ring,
     * which then fires in sequence, one transducer of each bank of eight at a time, as a Pioneer's
     * firmware fires it (ARIA reads the firmware's {@code SonarCycle} from the robot's config packet,
     * {@code ArRobotConfigPacketReader.cpp}; ARIA's parameter files do not carry it). Absent or 0:
     * every transducer fires every step.
     *
     * @param file the {@code .p} file
     * @return the ms between firings, 0 to 10000
     * @throws ParameterFileException naming the file, the line and the rule for a bad value
     * @throws UncheckedIOException   when the file cannot be read
     */
    public static int sonarCycle(Path file) {
        List<String> lines = lines(file);
        int cycle = 0;
        for (int i = 0; i < lines.size(); i++) {
            String[] words = stripComment(lines.get(i)).trim().split("\\s+");
            if (!words[0].equalsIgnoreCase("sonarcycle")) {
                continue;
            }
            String v = value(file, i + 1, words);
            try {
                cycle = Integer.parseInt(v);
            } catch (NumberFormatException e) {
                throw new ParameterFileException(file, i + 1, words[0] + " " + ParameterRules.quote(v)
                        + " is not a whole number of ms");
            }
            if (cycle < 0 || cycle > MAX_SONAR_CYCLE_MS) {
                throw new ParameterFileException(file, i + 1, words[0] + " is " + v
                        + " but must be 0 (every step) to " + MAX_SONAR_CYCLE_MS + " ms");
            }
        }
        return cycle;
    }

    private static List<String> lines(Path file) {
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(file);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read robot parameter file " + file, e);
        }
        return lines(file, bytes);
    }

    /**
     * @return the file's lines, read as UTF-8 (a leading byte order mark skipped)
     * @throws ParameterFileException naming the line and the offset of the first byte that is not UTF-8
     */
    static List<String> lines(Path file, byte[] bytes) {
        ByteBuffer in = ByteBuffer.wrap(bytes);
        CharBuffer text = CharBuffer.allocate(bytes.length);
        CoderResult result = StandardCharsets.UTF_8.newDecoder().decode(in, text, true);
        if (result.isError()) {
            int at = in.position();
            int line = 1;
            for (int i = 0; i < at; i++) {
                line += bytes[i] == '\n' || bytes[i] == '\r' && bytes[i + 1] != '\n' ? 1 : 0;
            }
            throw new ParameterFileException(file, line, String.format(
                    "byte 0x%02x at byte offset %d is not UTF-8: a parameter file is UTF-8 text", bytes[at] & 0xff, at));
        }
        String s = text.flip().toString();
        return (s.startsWith("\ufeff") ? s.substring(1) : s).lines().toList();
    }

    static RobotParameters parse(Path file, List<String> lines) {
        ParameterRules rules = new ParameterRules(file, ParameterRules.P_FORM);
        boolean versionSeen = false;
        String section = "";

        for (int i = 0; i < lines.size(); i++) {
            int lineNo = i + 1;
            String line = stripComment(lines.get(i)).trim();
            if (line.isEmpty()) {
                continue;
            }
            checkLine(file, lineNo, line);
            String[] words = line.split("\\s+");
            String key = words[0].toLowerCase(Locale.ROOT);
            if (key.equals("configversion")) {
                versionSeen = true;
                continue;
            }
            if (!versionSeen) {
                throw new ParameterFileException(file, lineNo,
                        "expected 'ConfigVersion 2.0' before " + ParameterRules.quote(words[0]));
            }
            String header = sectionName(line);
            if (header != null) {
                section = header;
                continue;
            }
            if (AriaKeys.isSonarBoard(section) || LATER_LASER.matcher(section).matches() && key.startsWith("laser")) {
                // a board's SonarMaxRange is the board's, and RoboSim models the first laser only
                if (!AriaKeys.isAriaOnly(key) && !ParameterRules.isNumber(key)) {
                    rules.unknownKey(words[0], lineNo);
                }
                continue;
            }
            switch (key) {
                case "class" -> rules.robotClass(value(file, lineNo, words));
                case "subclass" -> rules.subclass(value(file, lineNo, words));
                case "robotshape" -> rules.shape(value(file, lineNo, words), lineNo);
                case "hasgripper" -> rules.hasGripper(value(file, lineNo, words), lineNo);
                case "sonarnum" -> rules.sonarNum(value(file, lineNo, words), lineNo);
                case "sonarunit" -> {
                    // ARIA's MTX lines add board, unit, gain, threshold, range and a flag: RoboSim models the pose
                    if (words.length < 5) {
                        throw new ParameterFileException(file, lineNo,
                                "SonarUnit needs at least 4 values (index x y th), found " + (words.length - 1));
                    }
                    rules.sonarUnit(words[1], words[2], words[3], words[4], lineNo);
                }
                default -> {
                    if (ParameterRules.isNumber(key)) {
                        rules.number(words[0], value(file, lineNo, words), lineNo);
                    } else if (!AriaKeys.isAriaOnly(key)) {
                        rules.unknownKey(words[0], lineNo);
                    }
                }
            }
        }
        if (!versionSeen) {
            throw new ParameterFileException(file, 0, "no 'ConfigVersion 2.0' line: not an ARIA parameter file");
        }
        return rules.build();
    }

    /**
     * Holds a line's content (its comment aside) to {@value #MAX_LINE_CHARS} characters without control
     * characters but tabs, so that what an error quotes of it is short and cannot write to a terminal.
     */
    private static void checkLine(Path file, int lineNo, String line) {
        if (line.length() > MAX_LINE_CHARS || line.chars().anyMatch(c -> c != '\t' && Character.isISOControl(c))) {
            throw new ParameterFileException(file, lineNo, "the line " + ParameterRules.quote(line) + " is not a"
                    + " parameter line: a line holds at most " + MAX_LINE_CHARS + " characters before its comment,"
                    + " none of them a control character but a tab");
        }
    }

    /** @return the section a {@code Section name} or {@code [name]} line opens, or null for any other line */
    static String sectionName(String line) {
        if (line.startsWith("[") && line.endsWith("]")) {
            return line.substring(1, line.length() - 1).trim();
        }
        String[] words = line.split("\\s+", 2);
        if (words[0].equalsIgnoreCase("section")) {
            return words.length > 1 ? words[1].trim() : "";
        }
        return null;
    }

    private static String value(Path file, int lineNo, String[] words) {
        if (words.length < 2) {
            throw new ParameterFileException(file, lineNo, words[0] + " has no value");
        }
        return words[1];
    }

    static String stripComment(String line) {
        int semicolon = line.indexOf(';');
        return semicolon >= 0 ? line.substring(0, semicolon) : line;
    }
}
