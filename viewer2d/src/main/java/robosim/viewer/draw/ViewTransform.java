package robosim.viewer.draw;

import robosim.protocol.WorldDescription;

/**
 * Maps world coordinates (mm, +y up) to image pixels (+y down, origin at the upper left) at one
 * uniform scale, so that the image keeps the world's aspect ratio. The world's upper left corner,
 * ({@code minX}, {@code minY + height}), maps to the image's: a map's world need not start at (0, 0).
 *
 * @param scale  pixels per mm, greater than 0
 * @param width  image width in pixels
 * @param height image height in pixels
 * @param left   the world x, mm, that maps to the image's left edge
 * @param top    the world y, mm, that maps to the image's top edge
 */
public record ViewTransform(double scale, int width, int height, double left, double top) {
    /** The tallest image drawn, so that a very narrow world cannot exhaust the heap. */
    public static final int MAX_HEIGHT = 16384;

    /**
     * The transform that fits the whole world into an image of the given width.
     *
     * @param world the world
     * @param width image width in pixels, at least 1
     * @return the transform
     * @throws IllegalArgumentException if the world's size is not positive and finite, or the
     *                                  image would be taller than {@value #MAX_HEIGHT} pixels
     */
    public static ViewTransform fit(WorldDescription world, int width) {
        positive("width", world.width(), world.name());
        positive("height", world.height(), world.name());
        if (width < 1) {
            throw new IllegalArgumentException(width + " was supplied for width: width must be at least 1 pixel");
        }
        double scale = width / world.width();
        long height = Math.max(1, Math.round(world.height() * scale));
        if (height > MAX_HEIGHT) {
            throw new IllegalArgumentException("world '" + world.name() + "' of " + world.width() + " x "
                    + world.height() + " mm drawn " + width + " pixels wide would be " + height
                    + " pixels high: the height must be at most " + MAX_HEIGHT);
        }
        return new ViewTransform(scale, width, (int) height, world.minX(), world.minY() + world.height());
    }

    private static void positive(String what, double value, String world) {
        if (!(value > 0) || !Double.isFinite(value)) {
            throw new IllegalArgumentException("world '" + world + "' has " + what + " " + value + " mm: "
                    + what + " must be greater than 0 and finite");
        }
    }

    /**
     * @param x world x in mm
     * @return image x in pixels
     */
    public double px(double x) {
        return (x - left) * scale;
    }

    /**
     * @param y world y in mm
     * @return image y in pixels
     */
    public double py(double y) {
        return (top - y) * scale;
    }
}
