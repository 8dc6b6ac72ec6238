package robosim.viewer.view3d;

import robosim.viewer.draw.RenderOptions;

/**
 * How a 3D image is drawn.
 *
 * @param width       image width in pixels, 1 to {@link RenderOptions#MAX_WIDTH}; the height
 *                    follows from the camera (see {@link Projection#heightFor}), and the key under it
 * @param camera      where the view looks from
 * @param light       where the light comes from
 * @param showNames   whether to label each robot with its name
 * @param showTrails  whether to draw the robots' paths on the floor, when given
 * @param showCaption whether to write the step and simulated time in the top left corner
 * @param showSonar   whether to draw each robot's sonar rays on the floor
 * @param showLaser   whether to draw each robot's laser scan on the floor
 * @param showKey     whether to draw the legend under the scene, as under a 2D picture
 */
public record SceneOptions(int width, Camera camera, Light light, boolean showNames, boolean showTrails,
                           boolean showCaption, boolean showSonar, boolean showLaser, boolean showKey) {
    /**
     * Checks the width and that camera and light are given.
     *
     * @param width       image width
     * @param camera      the camera
     * @param light       the light
     * @param showNames   whether to label robots
     * @param showTrails  whether to draw trails
     * @param showCaption whether to write the caption
     * @param showSonar   whether to draw sonar rays
     * @param showLaser   whether to draw laser scans
     * @param showKey     whether to draw the legend
     * @throws IllegalArgumentException naming the bad value
     */
    public SceneOptions {
        if (width < 1 || width > RenderOptions.MAX_WIDTH) {
            throw new IllegalArgumentException(width + " was supplied for width: width must be from 1 to "
                    + RenderOptions.MAX_WIDTH + " pixels");
        }
        if (camera == null || light == null) {
            throw new IllegalArgumentException("null was supplied for " + (camera == null ? "camera" : "light")
                    + ": it is required");
        }
    }

    /**
     * Options without sensor readings and without the legend, for callers written before those
     * could be drawn in 3D.
     *
     * @param width       image width
     * @param camera      the camera
     * @param light       the light
     * @param showNames   whether to label robots
     * @param showTrails  whether to draw trails
     * @param showCaption whether to write the caption
     * @throws IllegalArgumentException naming the bad value
     */
    public SceneOptions(int width, Camera camera, Light light, boolean showNames, boolean showTrails,
                        boolean showCaption) {
        this(width, camera, light, showNames, showTrails, showCaption, false, false, false);
    }

    /**
     * The default camera and light, names, caption, laser scans and the legend shown; no trails, no
     * sonar rays.
     *
     * @param width image width
     * @return the options
     */
    public static SceneOptions of(int width) {
        return new SceneOptions(width, Camera.DEFAULT, Light.DEFAULT, true, false, true, false, true, true);
    }

    /**
     * @param newCamera the camera
     * @return these options with it
     */
    public SceneOptions withCamera(Camera newCamera) {
        return new SceneOptions(width, newCamera, light, showNames, showTrails, showCaption, showSonar, showLaser,
                showKey);
    }

    /**
     * @param names   whether to label robots
     * @param trails  whether to draw trails
     * @param caption whether to write the caption
     * @return these options showing those
     */
    public SceneOptions showing(boolean names, boolean trails, boolean caption) {
        return new SceneOptions(width, camera, light, names, trails, caption, showSonar, showLaser, showKey);
    }

    /**
     * @param sonar whether to draw sonar rays
     * @param laser whether to draw laser scans
     * @return these options drawing those readings, or not
     */
    public SceneOptions withSensors(boolean sonar, boolean laser) {
        return new SceneOptions(width, camera, light, showNames, showTrails, showCaption, sonar, laser, showKey);
    }

    /**
     * @param key whether to draw the legend under the scene
     * @return these options with the legend drawn, or not
     */
    public SceneOptions withKey(boolean key) {
        return new SceneOptions(width, camera, light, showNames, showTrails, showCaption, showSonar, showLaser, key);
    }

    /**
     * @return what this scene shows, in the 2D options' terms, for the legend (see
     *         {@code WorldRenderer.solidKeyHeight})
     */
    public RenderOptions shown() {
        return new RenderOptions(width, showSonar, showNames, showLaser, false, showTrails, showCaption, false, false);
    }
}
