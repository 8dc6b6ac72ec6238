package robosim.env.world;

import java.util.Locale;

/**
 * The rectangle a world covers: x from {@code minX} to {@code minX + width}, y from {@code minY}
 * to {@code minY + height}, in mm.
 *
 * @param minX   left edge
 * @param minY   bottom edge
 * @param width  extent in x, greater than 0
 * @param height extent in y, greater than 0
 */
public record Bounds(double minX, double minY, double width, double height) {

    /** @return the right edge */
    public double maxX() {
        return minX + width;
    }

    /** @return the top edge */
    public double maxY() {
        return minY + height;
    }

    /**
     * @param x mm
     * @param y mm
     * @return whether the point lies inside or on the edge
     */
    public boolean contains(double x, double y) {
        return x >= minX && x <= maxX() && y >= minY && y <= maxY();
    }

    /**
     * How messages name the world's extent: {@code 6000 x 6000} for one that starts at (0, 0), else
     * also its corners, {@code 24000 x 51000 from (-4780, -27000) to (19220, 24000)}.
     *
     * @return the words
     */
    public String describe() {
        String size = number(width) + " x " + number(height);
        if (minX == 0 && minY == 0) {
            return size;
        }
        return size + " from (" + number(minX) + ", " + number(minY) + ") to (" + number(maxX()) + ", "
                + number(maxY()) + ")";
    }

    private static String number(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : String.format(Locale.ROOT, "%s", v);
    }
}
