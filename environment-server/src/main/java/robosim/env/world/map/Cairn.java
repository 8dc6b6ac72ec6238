package robosim.env.world.map;

import java.util.Arrays;

/**
 * A {@code Cairn:} line of a map: an object placed in the map, such as a {@code RobotHome}, a
 * {@code Dock}, a {@code Goal}, a {@code ForbiddenLine} or a {@code ForbiddenArea}.
 *
 * @param type   the cairn's type, as written
 * @param x      mm
 * @param y      mm
 * @param th     degrees
 * @param label  its label (the quoted name after {@code ICON}), without the quotes
 * @param fromTo for lines and areas, the from and to points x1, y1, x2, y2 as written (an area's
 *               corners are these turned by {@code th} about the map's origin); otherwise empty
 * @param line   the 1-based line it was read from
 */
public record Cairn(String type, double x, double y, double th, String label, double[] fromTo, int line) {

    /** Copies the points so the record stays immutable. */
    public Cairn {
        fromTo = fromTo.clone();
    }

    /** @return a copy of the from and to points, empty when the cairn has none */
    @Override
    public double[] fromTo() {
        return fromTo.clone();
    }

    /** Compares the points, not the array's identity. */
    @Override
    public boolean equals(Object o) {
        return o instanceof Cairn c && type.equals(c.type) && x == c.x && y == c.y && th == c.th
                && label.equals(c.label) && Arrays.equals(fromTo, c.fromTo) && line == c.line;
    }

    @Override
    public int hashCode() {
        return (type.hashCode() * 31 + Double.hashCode(x)) * 31 + line;
    }

    @Override
    public String toString() {
        return "Cairn[" + type + " (" + x + ", " + y + ", " + th + ") '" + label + "' " + Arrays.toString(fromTo)
                + " line " + line + "]";
    }
}
