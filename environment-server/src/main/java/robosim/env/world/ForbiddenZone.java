package robosim.env.world;

import java.util.Arrays;

/**
 * A forbidden line or area of a map ({@code ForbiddenLine}, {@code ForbiddenArea} cairns): where a
 * robot's program should not drive. It is not solid: sensors do not see it and bodies pass
 * through it, as in MobileSim; programs that respect it read it from the map themselves.
 *
 * @param area  whether it is an area (a ring of four corners) rather than a line (two ends)
 * @param xy    the points x0, y0, x1, y1, ...: two for a line, four corners for an area, mm
 * @param label the cairn's label, possibly empty
 * @param line  the 1-based line of its cairn in the map file
 */
public record ForbiddenZone(boolean area, double[] xy, String label, int line) {

    /** Copies the coordinates so the record stays immutable. */
    public ForbiddenZone {
        xy = xy.clone();
    }

    /** @return a copy of the points */
    @Override
    public double[] xy() {
        return xy.clone();
    }

    /** Compares the coordinates, not the array's identity. */
    @Override
    public boolean equals(Object o) {
        return o instanceof ForbiddenZone other && area == other.area && Arrays.equals(xy, other.xy)
                && label.equals(other.label) && line == other.line;
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(xy) * 31 + line;
    }

    @Override
    public String toString() {
        return "ForbiddenZone[area=" + area + ", xy=" + Arrays.toString(xy) + ", label=" + label + ", line=" + line
                + "]";
    }
}
