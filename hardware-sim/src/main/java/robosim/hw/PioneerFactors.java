package robosim.hw;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.logging.Logger;
import robosim.params.ConversionFactors;
import robosim.params.ParameterFileException;
import robosim.params.RobotParameterFiles;

/**
 * A Pioneer's conversion factors, found as ARIA finds them: in the {@code .p} parameter file named
 * after the subclass the robot server gives in its answer to SYNC2, each factor the file leaves out
 * taking ARIA's default. A subclass without a file (MobileSim's {@code p3dx-sh}, whose factors are
 * all 1) takes ARIA's defaults.
 */
final class PioneerFactors {
    private static final Logger LOG = Logger.getLogger(PioneerFactors.class.getName());

    private PioneerFactors() {
    }

    /**
     * @param subclass the robot server's subclass, for example {@code p3dx}
     * @return the factors of {@code <subclass>.p}, or ARIA's defaults if there is no such file
     * @throws ParameterFileException if the file has a factor that is not a number above 0
     */
    static ConversionFactors forSubclass(String subclass) {
        Path file;
        try {
            file = RobotParameterFiles.resolve(subclass + ".p");
        } catch (IllegalArgumentException e) {
            LOG.info(() -> "no parameter file for the Pioneer subclass '" + subclass + "': ARIA's default conversion"
                    + " factors " + ConversionFactors.ARIA_DEFAULTS + " (" + e.getMessage() + ")");
            return ConversionFactors.ARIA_DEFAULTS;
        }
        return read(file);
    }

    /**
     * Reads the factors of a {@code .p} file: lines {@code Key value ; comment}, keys as ARIA spells
     * them, case aside.
     *
     * @param file the file
     * @return its factors, ARIA's defaults for those it leaves out
     * @throws ParameterFileException if the file cannot be read or a factor is not a number above 0
     */
    static ConversionFactors read(Path file) {
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.ISO_8859_1);
        } catch (IOException e) {
            throw new ParameterFileException(file, 0, "cannot be read: " + e.getMessage(), e);
        }
        Map<String, Double> found = new HashMap<>();
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            int comment = line.indexOf(';');
            String[] words = (comment >= 0 ? line.substring(0, comment) : line).trim().split("\\s+");
            String key = words[0].toLowerCase(Locale.ROOT);
            if (words.length < 2 || !key.endsWith("convfactor") && !key.equals("vel2divisor")) {
                continue;
            }
            found.put(key, factor(file, i + 1, words[0], words[1]));
        }
        ConversionFactors d = ConversionFactors.ARIA_DEFAULTS;
        return new ConversionFactors(found.getOrDefault("angleconvfactor", d.angleConvFactor()),
                found.getOrDefault("distconvfactor", d.distConvFactor()),
                found.getOrDefault("velconvfactor", d.velConvFactor()),
                found.getOrDefault("rangeconvfactor", d.rangeConvFactor()),
                found.getOrDefault("diffconvfactor", d.diffConvFactor()),
                found.getOrDefault("vel2divisor", d.vel2Divisor()));
    }

    private static double factor(Path file, int line, String key, String value) {
        try {
            double v = Double.parseDouble(value);
            if (Double.isFinite(v) && v > 0) {
                return v;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new ParameterFileException(file, line, "'" + value + "' was supplied for " + key
                + ": a conversion factor is a number above 0");
    }
}
