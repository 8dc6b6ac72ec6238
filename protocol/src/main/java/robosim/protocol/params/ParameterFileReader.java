package robosim.protocol.params;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * Reads ARIA's robot parameter files ({@code .p}): {@code ConfigVersion 2.0}, {@code Section}
 * lines, and {@code Key value ; comment} lines. Keys are matched without regard to case, as ARIA
 * does; keys RoboSim does not model (conversion factors, IO settings, ...) are accepted and
 * ignored so that real ARIA files load unchanged.
 *
 * <p>A key that is absent keeps the default of ARIA's {@code ArRobotParams}; a body length given
 * without {@code RobotLengthFront}/{@code RobotLengthRear} is split evenly about the centre.
 */
public final class ParameterFileReader {
    private static final Map<String, Double> DEFAULTS = Map.ofEntries(
            Map.entry("robotradius", 250.0),
            Map.entry("robotwidth", 400.0),
            Map.entry("robotlength", 500.0),
            Map.entry("robotlengthfront", 0.0),
            Map.entry("robotlengthrear", 0.0),
            Map.entry("maxvelocity", 2500.0),
            Map.entry("maxrvelocity", 500.0),
            Map.entry("transaccel", 300.0),
            Map.entry("transdecel", 300.0),
            Map.entry("rotaccel", 100.0),
            Map.entry("rotdecel", 100.0),
            Map.entry("diffconvfactor", 0.0056),
            Map.entry("sonarmaxrange", 5000.0));

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
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read robot parameter file " + file, e);
        }
        return parse(file, lines);
    }

    static RobotParameters parse(Path file, List<String> lines) {
        Map<String, Double> numbers = new HashMap<>(DEFAULTS);
        String robotClass = "Pioneer";
        String subclass = stripExtension(file.getFileName().toString());
        Integer sonarNum = null;
        int sonarNumLine = 0;
        Map<Integer, SonarUnit> sonars = new TreeMap<>();
        Map<Integer, Integer> sonarLines = new HashMap<>();
        boolean versionSeen = false;

        for (int i = 0; i < lines.size(); i++) {
            int lineNo = i + 1;
            String line = stripComment(lines.get(i)).trim();
            if (line.isEmpty()) {
                continue;
            }
            String[] words = line.split("\\s+");
            String key = words[0].toLowerCase(Locale.ROOT);
            if (key.equals("configversion")) {
                versionSeen = true;
                continue;
            }
            if (!versionSeen) {
                throw new ParameterFileException(file, lineNo,
                        "expected 'ConfigVersion 2.0' before '" + words[0] + "'");
            }
            switch (key) {
                case "section" -> { }
                case "class" -> robotClass = value(file, lineNo, words);
                case "subclass" -> subclass = value(file, lineNo, words);
                case "sonarnum" -> {
                    double n = number(file, lineNo, words[0], value(file, lineNo, words));
                    if (n < 0 || n > 32 || n != Math.rint(n)) {
                        throw new ParameterFileException(file, lineNo,
                                "SonarNum " + value(file, lineNo, words) + " must be a whole number from 0 to 32");
                    }
                    sonarNum = (int) n;
                    sonarNumLine = lineNo;
                }
                case "sonarunit" -> {
                    SonarUnit unit = sonarUnit(file, lineNo, words, sonarNum);
                    if (sonars.putIfAbsent(unit.index(), unit) != null) {
                        throw new ParameterFileException(file, lineNo,
                                "SonarUnit " + unit.index() + " is given twice");
                    }
                    sonarLines.put(unit.index(), lineNo);
                }
                default -> {
                    if (DEFAULTS.containsKey(key)) {
                        double v = number(file, lineNo, words[0], value(file, lineNo, words));
                        if (v < 0 || (v == 0 && !key.startsWith("robotlength"))) {
                            throw new ParameterFileException(file, lineNo,
                                    words[0] + " is " + words[1] + " but must be greater than 0");
                        }
                        numbers.put(key, v);
                    }
                }
            }
        }
        if (!versionSeen) {
            throw new ParameterFileException(file, 0, "no 'ConfigVersion 2.0' line: not an ARIA parameter file");
        }
        int expected = sonarNum == null ? sonars.size() : sonarNum;
        // a SonarUnit read before SonarNum escaped the index check; apply it now
        for (int index : sonars.keySet()) {
            if (sonarNum != null && index >= sonarNum) {
                throw new ParameterFileException(file, sonarLines.get(index),
                        "SonarUnit index " + index + " must be less than SonarNum " + sonarNum);
            }
        }
        for (int n = 0; n < expected; n++) {
            if (!sonars.containsKey(n)) {
                throw new ParameterFileException(file, sonarNumLine,
                        "SonarNum is " + expected + " but there is no SonarUnit " + n);
            }
        }
        double length = numbers.get("robotlength");
        double front = numbers.get("robotlengthfront");
        double rear = numbers.get("robotlengthrear");
        if (front == 0 || rear == 0) {
            front = length / 2;
            rear = length / 2;
        }
        return new RobotParameters(robotClass, subclass,
                numbers.get("robotradius"), numbers.get("robotwidth"), front, rear,
                numbers.get("maxvelocity"), numbers.get("maxrvelocity"),
                numbers.get("transaccel"), numbers.get("transdecel"),
                numbers.get("rotaccel"), numbers.get("rotdecel"),
                numbers.get("diffconvfactor"), numbers.get("sonarmaxrange"),
                List.copyOf(sonars.values()));
    }

    private static SonarUnit sonarUnit(Path file, int lineNo, String[] words, Integer sonarNum) {
        if (words.length != 5) {
            throw new ParameterFileException(file, lineNo,
                    "SonarUnit needs 4 values (index x y th), found " + (words.length - 1));
        }
        double index = number(file, lineNo, "SonarUnit index", words[1]);
        if (index < 0 || index != Math.rint(index)) {
            throw new ParameterFileException(file, lineNo,
                    "SonarUnit index " + words[1] + " must be a whole number from 0");
        }
        if (sonarNum != null && index >= sonarNum) {
            throw new ParameterFileException(file, lineNo,
                    "SonarUnit index " + words[1] + " must be less than SonarNum " + sonarNum);
        }
        return new SonarUnit((int) index,
                number(file, lineNo, "SonarUnit x", words[2]),
                number(file, lineNo, "SonarUnit y", words[3]),
                number(file, lineNo, "SonarUnit th", words[4]));
    }

    private static String value(Path file, int lineNo, String[] words) {
        if (words.length < 2) {
            throw new ParameterFileException(file, lineNo, words[0] + " has no value");
        }
        return words[1];
    }

    private static double number(Path file, int lineNo, String what, String text) {
        try {
            double v = Double.parseDouble(text);
            if (!Double.isFinite(v)) {
                throw new NumberFormatException();
            }
            return v;
        } catch (NumberFormatException e) {
            throw new ParameterFileException(file, lineNo, what + " '" + text + "' is not a number");
        }
    }

    private static String stripComment(String line) {
        int semicolon = line.indexOf(';');
        return semicolon >= 0 ? line.substring(0, semicolon) : line;
    }

    private static String stripExtension(String name) {
        int dot = name.lastIndexOf('.');
        return dot > 0 ? name.substring(0, dot) : name;
    }
}
