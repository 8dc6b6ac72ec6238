package robosim.params;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * A robot's conversion factors between the units of its firmware and ARIA's: what a Pioneer
 * protocol server needs to speak to an ARIA program in the robot's own units. ARIA's files give
 * them in {@code Section Conversion factors}.
 *
 * @param angleConvFactor radians per angle unit of the firmware (2π/4096)
 * @param distConvFactor  mm per distance unit of the firmware
 * @param velConvFactor   mm/s per speed unit of the firmware
 * @param rangeConvFactor mm per sonar range unit
 * @param diffConvFactor  rad/s per mm/s of wheel speed difference, as in {@code RobotParameters}
 * @param vel2Divisor     the divisor of a {@code VEL2} command's wheel speeds
 */
public record ConversionFactors(double angleConvFactor, double distConvFactor, double velConvFactor,
                                double rangeConvFactor, double diffConvFactor, double vel2Divisor) {

    /**
     * ARIA's defaults ({@code ArRobotParams}' constructor): a robot whose firmware counts in mm,
     * mm/s and 4096ths of a turn; the rotation factor is RoboSim's default {@code DiffConvFactor}.
     */
    public static final ConversionFactors ARIA_DEFAULTS = new ConversionFactors(0.001534, 1.0, 1.0, 1.0, 0.0056, 20);

    /** The keys, lower case, in the order of the record's components. */
    private static final List<String> KEYS = List.of("angleconvfactor", "distconvfactor", "velconvfactor",
            "rangeconvfactor", "diffconvfactor", "vel2divisor");

    /**
     * @param diffConvFactor the rotation factor
     * @return these factors with another rotation factor
     */
    public ConversionFactors withDiffConvFactor(double diffConvFactor) {
        return new ConversionFactors(angleConvFactor, distConvFactor, velConvFactor, rangeConvFactor, diffConvFactor,
                vel2Divisor);
    }

    /**
     * Reads the factors of an ARIA file's lines; a factor it does not give keeps ARIA's default.
     * Every factor is a number greater than 0, and a factor given twice keeps its last value.
     *
     * @param file  the file, for messages
     * @param lines its lines
     * @return the factors
     * @throws ParameterFileException naming the file, the line and the rule for a bad factor
     */
    static ConversionFactors read(Path file, List<String> lines) {
        Map<String, Double> found = new HashMap<>();
        for (int i = 0; i < lines.size(); i++) {
            String line = ParameterFileReader.stripComment(lines.get(i)).trim();
            String[] words = line.split("\\s+");
            String key = words[0].toLowerCase(Locale.ROOT);
            if (!KEYS.contains(key)) {
                continue;
            }
            if (words.length < 2) {
                throw new ParameterFileException(file, i + 1, words[0] + " has no value");
            }
            double v;
            try {
                v = Double.parseDouble(words[1]);
            } catch (NumberFormatException e) {
                throw new ParameterFileException(file, i + 1, words[0] + " " + ParameterRules.quote(words[1])
                        + " is not a number");
            }
            if (!(v > 0) || !Double.isFinite(v)) {
                throw new ParameterFileException(file, i + 1, words[0] + " is " + words[1] + " but must be greater than 0");
            }
            found.put(key, v);
        }
        ConversionFactors d = ARIA_DEFAULTS;
        return new ConversionFactors(found.getOrDefault(KEYS.get(0), d.angleConvFactor),
                found.getOrDefault(KEYS.get(1), d.distConvFactor), found.getOrDefault(KEYS.get(2), d.velConvFactor),
                found.getOrDefault(KEYS.get(3), d.rangeConvFactor), found.getOrDefault(KEYS.get(4), d.diffConvFactor),
                found.getOrDefault(KEYS.get(5), d.vel2Divisor));
    }

    /**
     * @return the factors as ARIA's parameter files name them, for a log line: {@code AngleConvFactor
     *         0.001534, DistConvFactor 0.485, ...}
     */
    public String describe() {
        return String.format(java.util.Locale.ROOT, "AngleConvFactor %s, DistConvFactor %s, VelConvFactor %s,"
                + " RangeConvFactor %s, DiffConvFactor %s, Vel2Divisor %s", angleConvFactor, distConvFactor,
                velConvFactor, rangeConvFactor, diffConvFactor, vel2Divisor);
    }
}
