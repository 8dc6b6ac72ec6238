package robosim.viewer.view3d;

import robosim.viewer.draw.RenderOptions;

/**
 * How a 3D image is drawn.
 *
 * @param width       image width in pixels, 1 to {@link RenderOptions#MAX_WIDTH}; the height
 *                    follows from the camera (see {@link Projection#heightFor})
 * @param camera      where the view looks from
 * @param light       where the light comes from
 * @param showNames   whether to label each robot with its name
 * @param showTrails  whether to draw the robots' paths on the floor, when given
 * @param showCaption whether to write the step and simulated time in the top left corner
 */
public record SceneOptions(int width, Camera camera, Light light, boolean showNames, boolean showTrails,
                           boolean showCaption) {
    /**
     * Checks the width and that camera and light are given.
     *
     * @param width       image width
     * @param camera      the camera
     * @param light       the light
     * @param showNames   whether to label robots
     * @param showTrails  whether to draw trails
     * @param showCaption whether to write the caption
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
     * The default camera and light, names and caption shown, no trails.
     *
     * @param width image width
     * @return the options
     */
    public static SceneOptions of(int width) {
        return new SceneOptions(width, Camera.DEFAULT, Light.DEFAULT, true, false, true);
    }

    /**
     * @param newCamera the camera
     * @return these options with it
     */
    public SceneOptions withCamera(Camera newCamera) {
        return new SceneOptions(width, newCamera, light, showNames, showTrails, showCaption);
    }

    /**
     * @param newLight the light
     * @return these options with it
     */
    public SceneOptions withLight(Light newLight) {
        return new SceneOptions(width, camera, newLight, showNames, showTrails, showCaption);
    }

    /**
     * @param names   whether to label robots
     * @param trails  whether to draw trails
     * @param caption whether to write the caption
     * @return these options showing those
     */
    public SceneOptions showing(boolean names, boolean trails, boolean caption) {
        return new SceneOptions(width, camera, light, names, trails, caption);
    }
}
