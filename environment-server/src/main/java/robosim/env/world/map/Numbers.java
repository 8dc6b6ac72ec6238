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
