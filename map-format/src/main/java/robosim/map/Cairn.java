package robosim.map;

import java.util.Arrays;

/**
 * A {@code Cairn:} line of a map: an object placed in the map, such as a {@code RobotHome}, a
 * {@code Dock}, a {@code Goal}, a {@code ForbiddenLine} or a {@code ForbiddenArea}. Its values are
 * those ARIA's {@code ArMapObject::createMapObject} (ArMapObject.cpp) reads:
 * {@code Type x y th "description" ICON "name" [x1 y1 x2 y2] ["description"]}.
 *
 * @param type        the cairn's type, as written
 * @param x           mm
 * @param y           mm
 * @param th          degrees
 * @param description its description: the quoted string after the name (after the from and to
 *                    points when it has them), else the quoted string after {@code th}, as ARIA's
 *                    {@code ArMapObject::setObjectDescription} takes it; without the quotes
 * @param icon        the word after the first quoted string ({@code ICON}, or {@code ID=n})
 * @param label       its label (the quoted name after the icon), without the quotes
 * @param fromTo      for lines and areas, the from and to points x1, y1, x2, y2 as written (an area's
 *                    corners are these turned by {@code th} about the map's origin); otherwise empty
 * @param line        the 1-based line it was read from
 */
public record Cairn(String type, double x, double y, double th, String description, String icon, String label,
                    double[] fromTo, int line) {

    /** Copies the points so the record stays immutable. */
    public Cairn {
        fromTo = fromTo.clone();
    }

    /**
     * A cairn with no description and the icon {@code ICON}, as most maps write them.
     *
     * @param type   the cairn's type
     * @param x      mm
     * @param y      mm
     * @param th     degrees
     * @param label  its label
     * @param fromTo its from and to points, or empty
     * @param line   the 1-based line it was read from
     */
    public Cairn(String type, double x, double y, double th, String label, double[] fromTo, int line) {
        this(type, x, y, th, "", "ICON", label, fromTo, line);
    }

    /** @return a copy of the from and to points, empty when the cairn has none */
    @Override
    public double[] fromTo() {
        return fromTo.clone();
    }

    /** @return whether it has from and to points: a line or an area */
    public boolean hasFromTo() {
        return fromTo.length > 0;
    }

    /** Compares the points, not the array's identity. */
    @Override
    public boolean equals(Object o) {
        return o instanceof Cairn c && type.equals(c.type) && x == c.x && y == c.y && th == c.th
                && description.equals(c.description) && icon.equals(c.icon)
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
