package robosim.map;

import java.nio.file.Path;
import java.util.regex.Pattern;

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
            throw new MapFileException(file, line, what + " '" + MapLines.excerpt(token) + "' is not a number");
        }
        double v = Double.parseDouble(token);
        if (!(Math.abs(v) <= MapReader.MAX_MAGNITUDE)) {
            throw new MapFileException(file, line, what + " " + MapLines.excerpt(token) + " must be from"
                    + " -1000000000 to 1000000000:"
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
        return wholeNumber(token.toCharArray(), 0, token.length());
    }

    /** @return the characters' value if they are an optional sign and 1 to 15 digits, else NaN */
    private static double wholeNumber(char[] c, int from, int to) {
        int i = to > from && (c[from] == '-' || c[from] == '+') ? from + 1 : from;
        if (to == i || to - i > 15) {
            return Double.NaN;
        }
        long v = 0;
        for (int k = i; k < to; k++) {
            char d = c[k];
            if (d < '0' || d > '9') {
                return Double.NaN;
            }
            v = v * 10 + (d - '0');
        }
        // negated as a long, so "-0" is 0 as it always was
        return c[from] == '-' ? -v : v;
    }

    /**
     * The coordinate written from {@code from} to {@code to} of a line, read in place when it is a
     * whole number of at most 10^8 either way (a scanned map's are), else as {@link #coordinate}.
     */
    static double coordinate(Path file, int line, char[] c, int from, int to, String what) {
        double whole = wholeNumber(c, from, to);
        if (Math.abs(whole) <= MapReader.MAX_COORDINATE) {
            return whole;
        }
        return coordinate(file, line, new String(c, from, to - from), what);
    }

    /** @return the token as a coordinate, within {@link MapReader#MAX_COORDINATE} either way */
    static double coordinate(Path file, int line, String token, String what) {
        double v = parse(file, line, token, what);
        if (Math.abs(v) > MapReader.MAX_COORDINATE) {
            throw new MapFileException(file, line, what + " " + MapLines.excerpt(token)
                    + " must be from -100000000 to 100000000 (100 km in mm)");
        }
        return v;
    }
}
