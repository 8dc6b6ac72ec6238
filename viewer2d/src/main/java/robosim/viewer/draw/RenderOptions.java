package robosim.viewer.draw;

/**
 * How an image is drawn. The image height follows from the width and the world's aspect ratio.
 * Heat sources are always drawn: they are part of the static world.
 *
 * @param width        image width in pixels, from 1 to {@value #MAX_WIDTH}
 * @param showSonar    whether to draw each robot's sonar rays
 * @param showNames    whether to label each robot with its name
 * @param showLaser    whether to draw each robot's latest laser scan
 * @param showOdometry whether to draw, as a dashed outline, where a robot believes it is when its
 *                     odometry is more than 1 mm or 0.5° away from its true pose
 * @param showTrails   whether to draw the path each robot has taken, when a {@link Trails} is given
 * @param showCaption  whether to write the step and simulated time in the key under the world
 * @param showGrid     whether to draw a light grid of round-length squares (see {@link ScaleBar#gridSpacing})
 * @param showDrawings whether to draw the robots' drawings (their known maps, claimed frontiers)
 *                     carried by the snapshot, see {@link Drawings}
 */
public record RenderOptions(int width, boolean showSonar, boolean showNames, boolean showLaser,
                            boolean showOdometry, boolean showTrails, boolean showCaption, boolean showGrid,
                            boolean showDrawings) {
    /** The widest image drawn, so that a bad option cannot exhaust the heap. */
    public static final int MAX_WIDTH = 8192;

    /**
     * Checks the width.
     *
     * @param width        image width in pixels, from 1 to {@value #MAX_WIDTH}
     * @param showSonar    whether to draw sonar rays
     * @param showNames    whether to label robots
     * @param showLaser    whether to draw laser scans
     * @param showOdometry whether to draw the odometry pose when it is off the true pose
     * @param showTrails   whether to draw the robots' paths
     * @param showCaption  whether to write the step and time
     * @param showGrid     whether to draw the grid
     * @param showDrawings whether to draw the robots' drawings
     * @throws IllegalArgumentException if the width is out of range
     */
    public RenderOptions {
        if (width < 1 || width > MAX_WIDTH) {
            throw new IllegalArgumentException(width + " was supplied for width: width must be from 1 to "
                    + MAX_WIDTH + " pixels");
        }
    }

    /**
     * Options with the caption and without trails.
     *
     * @param width        image width in pixels, from 1 to {@value #MAX_WIDTH}
     * @param showSonar    whether to draw sonar rays
     * @param showNames    whether to label robots
     * @param showLaser    whether to draw laser scans
     * @param showOdometry whether to draw the odometry pose when it is off the true pose
     * @throws IllegalArgumentException if the width is out of range
     */
    public RenderOptions(int width, boolean showSonar, boolean showNames, boolean showLaser, boolean showOdometry) {
        this(width, showSonar, showNames, showLaser, showOdometry, false, true, false, false);
    }

    /**
     * Options that show laser scans and the odometry pose, for callers written before those could
     * be chosen.
     *
     * @param width     image width in pixels, from 1 to {@value #MAX_WIDTH}
     * @param showSonar whether to draw sonar rays
     * @param showNames whether to label robots
     * @throws IllegalArgumentException if the width is out of range
     */
    public RenderOptions(int width, boolean showSonar, boolean showNames) {
        this(width, showSonar, showNames, true, true);
    }

    /**
     * The usual options: sonar rays, names, laser scans and the odometry pose shown.
     *
     * @param width image width in pixels
     * @return the options
     */
    public static RenderOptions of(int width) {
        return new RenderOptions(width, true, true);
    }

    /**
     * @param show whether to draw laser scans
     * @return these options with laser scans shown or hidden
     */
    public RenderOptions withLaser(boolean show) {
        return new RenderOptions(width, showSonar, showNames, show, showOdometry, showTrails, showCaption, showGrid,
                showDrawings);
    }

    /**
     * @param show whether to draw the odometry pose when it is off the true pose
     * @return these options with the odometry pose shown or hidden
     */
    public RenderOptions withOdometry(boolean show) {
        return new RenderOptions(width, showSonar, showNames, showLaser, show, showTrails, showCaption, showGrid,
                showDrawings);
    }

    /**
     * @param show whether to draw sonar rays
     * @return these options with sonar rays shown or hidden
     */
    public RenderOptions withSonar(boolean show) {
        return new RenderOptions(width, show, showNames, showLaser, showOdometry, showTrails, showCaption, showGrid,
                showDrawings);
    }

    /**
     * @param show whether to label robots with their names
     * @return these options with names shown or hidden
     */
    public RenderOptions withNames(boolean show) {
        return new RenderOptions(width, showSonar, show, showLaser, showOdometry, showTrails, showCaption, showGrid,
                showDrawings);
    }

    /**
     * @param show whether to draw the robots' paths
     * @return these options with trails shown or hidden
     */
    public RenderOptions withTrails(boolean show) {
        return new RenderOptions(width, showSonar, showNames, showLaser, showOdometry, show, showCaption, showGrid,
                showDrawings);
    }

    /**
     * @param show whether to write the step and time on the image
     * @return these options with the caption shown or hidden
     */
    public RenderOptions withCaption(boolean show) {
        return new RenderOptions(width, showSonar, showNames, showLaser, showOdometry, showTrails, show, showGrid,
                showDrawings);
    }

    /**
     * @param show whether to draw a light grid of round-length squares
     * @return these options with the grid shown or hidden
     */
    public RenderOptions withGrid(boolean show) {
        return new RenderOptions(width, showSonar, showNames, showLaser, showOdometry, showTrails, showCaption, show,
                showDrawings);
    }

    /**
     * @param show whether to draw the robots' drawings
     * @return these options with the drawings shown or hidden
     */
    public RenderOptions withDrawings(boolean show) {
        return new RenderOptions(width, showSonar, showNames, showLaser, showOdometry, showTrails, showCaption, showGrid,
                show);
    }

    /**
     * @param newWidth image width in pixels
     * @return these options at that width
     */
    public RenderOptions withWidth(int newWidth) {
        return new RenderOptions(newWidth, showSonar, showNames, showLaser, showOdometry, showTrails, showCaption, showGrid,
                showDrawings);
    }
}
