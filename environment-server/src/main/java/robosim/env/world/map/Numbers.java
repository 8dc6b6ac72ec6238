package robosim.env.world.map;

import java.nio.file.Path;
import java.util.regex.Pattern;
import robosim.env.world.World;

/** Checks the numbers of a map file against the bounds of a world file. */
final class Numbers {
    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?");

    private Numbers() {
    }

    /** @return the token as a finite number of at most 10^9 either way */
    static double parse(Path file, int line, String token, String what) {
        double whole = wholeNumber(token);
        if (!Double.isNaN(whole) && Math.abs(whole) <= MapReader.MAX_MAGNITUDE) {
            return whole;
        }
        if (!NUMBER.matcher(token).matches()) {
            throw new MapFileException(file, line, what + " '" + MapReader.shorten(token) + "' is not a number");
        }
        double v = Double.parseDouble(token);
        if (!(Math.abs(v) <= MapReader.MAX_MAGNITUDE)) {
            throw new MapFileException(file, line, what + " " + token + " must be from -1000000000 to 1000000000:"
                    + " no number in a map file is larger");
        }
        return v;
    }

    /**
     * The common case first, without a regular expression: a map's numbers are mostly whole
     * millimetres, and a scanned map has 10^5 of them.
     *
     * @return the token's value if it is an optional sign and 1 to 15 digits, else NaN
     */
    private static double wholeNumber(String token) {
        int n = token.length();
        int i = n > 0 && (token.charAt(0) == '-' || token.charAt(0) == '+') ? 1 : 0;
        if (n == i || n - i > 15) {
            return Double.NaN;
        }
        long v = 0;
        for (int k = i; k < n; k++) {
            char c = token.charAt(k);
            if (c < '0' || c > '9') {
                return Double.NaN;
            }
            v = v * 10 + (c - '0');
        }
        return token.charAt(0) == '-' ? -v : v;
    }

    /** @return the token as a coordinate, within {@link World#MAX_SIZE} either way */
    static double coordinate(Path file, int line, String token, String what) {
        double v = parse(file, line, token, what);
        if (Math.abs(v) > World.MAX_SIZE) {
            throw new MapFileException(file, line, what + " " + token
                    + " must be from -100000000 to 100000000 (100 km in mm)");
        }
        return v;
    }
}
