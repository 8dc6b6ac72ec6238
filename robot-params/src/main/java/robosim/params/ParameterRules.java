package robosim.params;

import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.logging.Logger;
import robosim.protocol.LogLimiter;

/**
 * The rules both forms of a robot parameter file share, so that a {@code .p} file and its
 * {@code .xml} twin give equal records: ARIA's defaults, which numbers must be positive, and the
 * sonar count against the sonar units. Each form's reader feeds in the values with the line they
 * came from and names them in its own spelling, so that messages quote the file as written.
 */
final class ParameterRules {
    /**
     * How a form spells the sonar names in its messages.
     *
     * @param sonarNum  the sonar count
     * @param sonarUnit one sonar transducer
     * @param index     a transducer's number
     */
    record Spelling(String sonarNum, String sonarUnit, String index) {
    }

    /** How the {@code .p} form spells the sonar names. */
    static final Spelling P_FORM = new Spelling("SonarNum", "SonarUnit", "index");
    /** How the XML form spells the sonar names. */
    static final Spelling XML_FORM = new Spelling("sonarNum", "sonarUnit", "number");

    /** The most sonar transducers a file may declare; bounds what a broken file can make us allocate. */
    static final int MAX_SONARS = 32;

    private enum Sign { POSITIVE, NOT_NEGATIVE, ANY }

    private record Rule(double defaultValue, Sign sign) {
    }

    /** Numeric keys, lower case, with ARIA's {@code ArRobotParams} defaults. */
    private static final Map<String, Rule> NUMBERS = Map.ofEntries(
            Map.entry("robotradius", new Rule(250, Sign.POSITIVE)),
            Map.entry("robotdiagonal", new Rule(120, Sign.POSITIVE)),
            Map.entry("robotwidth", new Rule(400, Sign.POSITIVE)),
            Map.entry("robotlength", new Rule(500, Sign.NOT_NEGATIVE)),
            Map.entry("robotlengthfront", new Rule(0, Sign.NOT_NEGATIVE)),
            Map.entry("robotlengthrear", new Rule(0, Sign.NOT_NEGATIVE)),
            Map.entry("maxvelocity", new Rule(2500, Sign.POSITIVE)),
            Map.entry("maxrvelocity", new Rule(500, Sign.POSITIVE)),
            Map.entry("transaccel", new Rule(300, Sign.POSITIVE)),
            Map.entry("transdecel", new Rule(300, Sign.POSITIVE)),
            Map.entry("rotaccel", new Rule(100, Sign.POSITIVE)),
            Map.entry("rotdecel", new Rule(100, Sign.POSITIVE)),
            // the desired limits below the absolute ones; RoboSim checks them but drives by the absolute ones
            Map.entry("transvelmax", new Rule(0, Sign.NOT_NEGATIVE)),
            Map.entry("rotvelmax", new Rule(0, Sign.NOT_NEGATIVE)),
            Map.entry("diffconvfactor", new Rule(0.0056, Sign.POSITIVE)),
            Map.entry("sonarmaxrange", new Rule(5000, Sign.POSITIVE)),
            Map.entry("laserx", new Rule(0, Sign.ANY)),
            Map.entry("lasery", new Rule(0, Sign.ANY)),
            Map.entry("laserth", new Rule(0, Sign.ANY)),
            // ARIA writes "LaserMaxRange 0" for "the laser's own default"
            Map.entry("lasermaxrange", new Rule(0, Sign.NOT_NEGATIVE)));

    /**
     * Keys where ARIA reads 0 as "keep the value in the robot's firmware": the simulated robot's
     * firmware holds the defaults above.
     */
    private static final Set<String> ZERO_KEEPS_FIRMWARE =
            Set.of("transaccel", "transdecel", "rotaccel", "rotdecel", "transvelmax", "rotvelmax");

    private static final Logger LOG = Logger.getLogger(ParameterRules.class.getName());

    private final Path file;
    /** What the file's one warning will say: keys nobody knows, sonars declared but not given. */
    private final List<String> unknownKeys = new ArrayList<>();
    private String sonarShortfall;
    private final Spelling spelling;
    private final Map<String, Double> numbers = new HashMap<>();
    private String robotClass = "Pioneer";
    private String subclass;
    private String shape = RobotParameters.RECTANGLE;
    private boolean hasGripper;
    private Integer sonarNum;
    private int sonarNumLine;
    private final Map<Integer, SonarUnit> sonars = new TreeMap<>();
    private final Map<Integer, Integer> sonarLines = new HashMap<>();

    /**
     * @param file     the file read, named in every message; its name without extension is the
     *                 default subclass
     * @param spelling how the file's form spells the sonar names
     */
    ParameterRules(Path file, Spelling spelling) {
        this.file = file;
        this.spelling = spelling;
        String name = file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        this.subclass = dot > 0 ? name.substring(0, dot) : name;
        NUMBERS.forEach((key, rule) -> numbers.put(key, rule.defaultValue()));
    }

    /** @return whether {@code key} (any case) names a numeric parameter */
    static boolean isNumber(String key) {
        return NUMBERS.containsKey(key.toLowerCase(Locale.ROOT));
    }

    /**
     * @param text text from a parameter file
     * @return it as an error quotes it: in single quotes, escaped and cut short (see {@link LogLimiter#excerpt})
     */
    static String quote(String text) {
        return "'" + LogLimiter.excerpt(text) + "'";
    }

    /** @return a problem with this file at {@code line} (0: the whole file) */
    ParameterFileException error(int line, String rule) {
        return new ParameterFileException(file, line, rule);
    }

    void robotClass(String value) {
        robotClass = value;
    }

    void subclass(String value) {
        subclass = value;
    }

    /** Sets whether a Pioneer gripper is mounted: {@code true}/{@code false} or {@code 1}/{@code 0}. */
    void hasGripper(String value, int line) {
        String v = value.toLowerCase(Locale.ROOT);
        if (!Set.of("true", "false", "1", "0").contains(v)) {
            throw error(line, "HasGripper " + quote(value) + " must be true, false, 1 or 0");
        }
        hasGripper = v.equals("true") || v.equals("1");
    }

    /** Sets the body's shape: {@code rectangle} or {@code round}. */
    void shape(String value, int line) {
        String v = value.toLowerCase(java.util.Locale.ROOT);
        if (!v.equals(RobotParameters.RECTANGLE) && !v.equals(RobotParameters.ROUND)) {
            throw error(line, "RobotShape " + quote(value) + " must be rectangle or round");
        }
        shape = v;
    }

    /**
     * Sets a numeric parameter.
     *
     * @param key  the key (any case) as the file writes it, for messages
     * @param text the value as written
     * @param line where
     */
    void number(String key, String text, int line) {
        number(key, key, text, line);
    }

    /**
     * Sets a numeric parameter that the file names differently from its key.
     *
     * @param key  the key (any case), for example {@code LaserMaxRange}
     * @param name how the file names it, for messages, for example {@code laser maxRange}
     * @param text the value as written
     * @param line where
     */
    void number(String key, String name, String text, int line) {
        Rule rule = NUMBERS.get(key.toLowerCase(Locale.ROOT));
        double v = parse(name, text, line);
        if (v == 0 && ZERO_KEEPS_FIRMWARE.contains(key.toLowerCase(Locale.ROOT))) {
            numbers.put(key.toLowerCase(Locale.ROOT), rule.defaultValue());
            return;
        }
        if (rule.sign() == Sign.POSITIVE && v <= 0) {
            throw error(line, name + " is " + LogLimiter.excerpt(text) + " but must be greater than 0");
        }
        if (rule.sign() == Sign.NOT_NEGATIVE && v < 0) {
            throw error(line, name + " is " + LogLimiter.excerpt(text) + " but must not be negative");
        }
        numbers.put(key.toLowerCase(Locale.ROOT), v);
    }

    /**
     * Notes a key that neither RoboSim nor ARIA defines; it is ignored, and named in the file's one
     * warning.
     *
     * @param key  the key as written
     * @param line where
     */
    void unknownKey(String key, int line) {
        unknownKeys.add(LogLimiter.excerpt(key) + " (line " + line + ")");
    }

    /** A broken file may hold thousands of unknown keys; the warning names this many and counts the rest. */
    private static final int NAMED_UNKNOWN_KEYS = 20;

    /** @return the robot's class so far */
    String robotClassName() {
        return robotClass;
    }

    /** @return the robot's subclass so far (the file's name without extension when it gives none) */
    String subclassName() {
        return subclass;
    }

    /**
     * Takes the sonar ring of the robot's model, for a file that gives no sonar units of its own.
     *
     * @param units the model's units, numbered 0, 1, ...
     * @param line  the line the model was chosen by (the subclass), for messages
     * @throws ParameterFileException if the file's sonar count differs from the model's
     */
    void modelSonars(List<SonarUnit> units, int line) {
        if (sonarNum != null && sonarNum != units.size()) {
            throw error(sonarNumLine, spelling.sonarNum() + " is " + sonarNum + " but the " + subclass
                    + " model has " + units.size() + " sonars and the file gives none of its own");
        }
        for (SonarUnit u : units) {
            sonars.put(u.index(), u);
            sonarLines.put(u.index(), line);
        }
    }

    void sonarNum(String text, int line) {
        double n = parse(spelling.sonarNum(), text, line);
        if (n < 0 || n > MAX_SONARS || n != Math.rint(n)) {
            throw error(line, spelling.sonarNum() + " " + LogLimiter.excerpt(text)
                    + " must be a whole number from 0 to " + MAX_SONARS);
        }
        sonarNum = (int) n;
        sonarNumLine = line;
    }

    /**
     * Adds a sonar transducer.
     *
     * @param index its number as written
     * @param x     mm forward, as written
     * @param y     mm left, as written
     * @param th    heading in degrees, as written
     * @param line  where
     */
    void sonarUnit(String index, String x, String y, String th, int line) {
        String unit = spelling.sonarUnit();
        double n = parse(unit + " " + spelling.index(), index, line);
        if (n < 0 || n != Math.rint(n)) {
            throw error(line, unit + " " + spelling.index() + " " + LogLimiter.excerpt(index)
                    + " must be a whole number from 0");
        }
        if (sonarNum != null && n >= sonarNum) {
            throw error(line, unit + " " + spelling.index() + " " + LogLimiter.excerpt(index) + " must be less than "
                    + spelling.sonarNum() + " " + sonarNum);
        }
        if (n >= MAX_SONARS) {
            throw error(line, unit + " " + spelling.index() + " " + LogLimiter.excerpt(index)
                    + " must be less than " + MAX_SONARS);
        }
        SonarUnit sonar = new SonarUnit((int) n, parse(unit + " x", x, line), parse(unit + " y", y, line),
                parse(unit + " th", th, line));
        if (sonars.putIfAbsent(sonar.index(), sonar) != null) {
            throw error(line, unit + " " + sonar.index() + " is given twice");
        }
        sonarLines.put(sonar.index(), line);
    }

    /**
     * Applies the rules that need the whole file and makes the record.
     *
     * @return the robot's parameters
     * @throws ParameterFileException if a sonar unit is missing or lies beyond a later sonar count
     */
    RobotParameters build() {
        int expected = sonarNum == null ? sonars.size() : sonarNum;
        // a sonar unit read before the sonar count escaped the index check; apply it now
        for (int index : sonars.keySet()) {
            if (sonarNum != null && index >= sonarNum) {
                throw error(sonarLines.get(index), spelling.sonarUnit() + " " + spelling.index() + " " + index
                        + " must be less than " + spelling.sonarNum() + " " + sonarNum);
            }
        }
        if (expected > sonars.size() && sonars.keySet().stream().allMatch(n -> n < sonars.size())) {
            // ARIA's powerbot.p declares 32 and lists 31: the robot has the units the file gives
            sonarShortfall = spelling.sonarNum() + " is " + expected + " (line " + sonarNumLine + ") but only "
                    + sonars.size() + " " + spelling.sonarUnit() + (sonars.size() == 1 ? " is" : "s are")
                    + " given; the robot has those " + sonars.size();
            expected = sonars.size();
        }
        for (int n = 0; n < expected; n++) {
            if (!sonars.containsKey(n)) {
                throw error(sonarNumLine, spelling.sonarNum() + " is " + expected + " but there is no "
                        + spelling.sonarUnit() + " " + n);
            }
        }
        warn();
        double length = numbers.get("robotlength");
        double front = numbers.get("robotlengthfront");
        double rear = numbers.get("robotlengthrear");
        if (front == 0 || rear == 0) {
            front = length / 2;
            rear = length / 2;
        }
        double laserRange = numbers.get("lasermaxrange");
        return new RobotParameters(robotClass, subclass,
                numbers.get("robotradius"), numbers.get("robotwidth"), front, rear,
                numbers.get("maxvelocity"), numbers.get("maxrvelocity"),
                numbers.get("transaccel"), numbers.get("transdecel"),
                numbers.get("rotaccel"), numbers.get("rotdecel"),
                numbers.get("diffconvfactor"), numbers.get("sonarmaxrange"),
                List.copyOf(sonars.values()),
                numbers.get("laserx"), numbers.get("lasery"), numbers.get("laserth"),
                laserRange == 0 ? RobotParameters.DEFAULT_LASER_MAX_RANGE : laserRange, shape, hasGripper);
    }

    /** Logs the file's one warning, if it has anything to warn of. */
    private void warn() {
        List<String> parts = new ArrayList<>();
        if (!unknownKeys.isEmpty()) {
            List<String> named = unknownKeys.subList(0, Math.min(unknownKeys.size(), NAMED_UNKNOWN_KEYS));
            int more = unknownKeys.size() - named.size();
            parts.add("ignored unknown key" + (unknownKeys.size() == 1 ? " " : "s ") + String.join(", ", named)
                    + (more > 0 ? " and " + more + " more" : ""));
        }
        if (sonarShortfall != null) {
            parts.add(sonarShortfall);
        }
        if (!parts.isEmpty()) {
            LOG.warning(file + ": " + String.join("; ", parts));
        }
    }

    private double parse(String what, String text, int line) {
        try {
            double v = Double.parseDouble(text);
            if (!Double.isFinite(v)) {
                throw new NumberFormatException();
            }
            return v;
        } catch (NumberFormatException e) {
            throw error(line, what + " " + quote(text) + " is not a number");
        }
    }
}
