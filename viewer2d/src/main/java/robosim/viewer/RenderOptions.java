package robosim.viewer;

/**
 * How a frame is drawn. The image height follows from the width and the world's aspect ratio.
 *
 * @param width     image width in pixels, from 1 to {@value #MAX_WIDTH}
 * @param showSonar whether to draw each robot's sonar rays
 * @param showNames whether to label each robot with its name
 */
public record RenderOptions(int width, boolean showSonar, boolean showNames) {
    /** The widest image drawn, so that a bad option cannot exhaust the heap. */
    public static final int MAX_WIDTH = 8192;

    /**
     * Checks the width.
     *
     * @param width     image width in pixels, from 1 to {@value #MAX_WIDTH}
     * @param showSonar whether to draw sonar rays
     * @param showNames whether to label robots
     * @throws IllegalArgumentException if the width is out of range
     */
    public RenderOptions {
        if (width < 1 || width > MAX_WIDTH) {
            throw new IllegalArgumentException(width + " was supplied for width: width must be from 1 to "
                    + MAX_WIDTH + " pixels");
        }
    }

    /**
     * The usual options: sonar rays and names shown.
     *
     * @param width image width in pixels
     * @return the options
     */
    public static RenderOptions of(int width) {
        return new RenderOptions(width, true, true);
    }
}
