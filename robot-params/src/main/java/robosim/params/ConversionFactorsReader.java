package robosim.params;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/** Reads the conversion factors of an ARIA parameter file; keys absent keep ARIA's defaults. */
final class ConversionFactorsReader {
    private ConversionFactorsReader() {
    }

    static ConversionFactors read(Path file) {
        ConversionFactors d = ConversionFactors.ARIA_DEFAULTS;
        if (!file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".p")) {
            return d;
        }
        double angle = d.angleConvFactor();
        double dist = d.distConvFactor();
        double vel = d.velConvFactor();
        double range = d.rangeConvFactor();
        double diff = d.diffConvFactor();
        double vel2 = d.vel2Divisor();
        try {
            for (String raw : Files.readAllLines(file)) {
                int semicolon = raw.indexOf(';');
                String[] w = (semicolon >= 0 ? raw.substring(0, semicolon) : raw).trim().split("\\s+");
                if (w.length < 2) {
                    continue;
                }
                double v;
                try {
                    v = Double.parseDouble(w[1]);
                } catch (NumberFormatException e) {
                    continue;
                }
                if (!(v > 0) || !Double.isFinite(v)) {
                    continue;
                }
                switch (w[0].toLowerCase(Locale.ROOT)) {
                    case "angleconvfactor" -> angle = v;
                    case "distconvfactor" -> dist = v;
                    case "velconvfactor" -> vel = v;
                    case "rangeconvfactor" -> range = v;
                    case "diffconvfactor" -> diff = v;
                    case "vel2divisor" -> vel2 = v;
                    default -> { }
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read robot parameter file " + file, e);
        }
        return new ConversionFactors(angle, dist, vel, range, diff, vel2);
    }
}
