package robosim.viewer.view3d;

/**
 * Where the 3D view looks from. The camera looks at the world's centre (or the robot it follows)
 * along a direction given by two angles, with an orthographic projection so that sizes do not
 * depend on distance.
 *
 * @param azimuth   the compass direction from the world's centre to the camera, degrees
 *                  counter-clockwise from +x: -90 looks from the south (the 2D view's bottom edge)
 * @param elevation the camera's angle above the ground, degrees, from {@value #MIN_ELEVATION} to
 *                  90 (straight down, as the 2D view)
 * @param zoom      magnification, from {@value #MIN_ZOOM} to {@value #MAX_ZOOM}; 1 fits the whole
 *                  world in the image
 */
public record Camera(double azimuth, double elevation, double zoom) {
    /** The lowest elevation: at the horizon no roof would show. */
    public static final double MIN_ELEVATION = 5;
    /** The smallest zoom. */
    public static final double MIN_ZOOM = 0.1;
    /** The largest zoom. */
    public static final double MAX_ZOOM = 50;
    /** From the south, 40° up, the whole world in view. */
    public static final Camera DEFAULT = new Camera(-90, 40, 1);

    /**
     * Checks the angles and the zoom; the azimuth is kept in (-180, 180].
     *
     * @param azimuth   degrees, any finite value
     * @param elevation degrees, {@value #MIN_ELEVATION} to 90
     * @param zoom      {@value #MIN_ZOOM} to {@value #MAX_ZOOM}
     * @throws IllegalArgumentException naming the value and the rule it breaks
     */
    public Camera {
        if (!Double.isFinite(azimuth)) {
            throw new IllegalArgumentException(azimuth + " was supplied for azimuth: it must be a finite number of degrees");
        }
        if (!(elevation >= MIN_ELEVATION && elevation <= 90)) {
            throw new IllegalArgumentException(elevation + " was supplied for elevation: it must be from "
                    + MIN_ELEVATION + " to 90 degrees");
        }
        if (!(zoom >= MIN_ZOOM && zoom <= MAX_ZOOM)) {
            throw new IllegalArgumentException(zoom + " was supplied for zoom: it must be from " + MIN_ZOOM
                    + " to " + MAX_ZOOM);
        }
        double a = Math.IEEEremainder(azimuth, 360);
        azimuth = a == -180 ? 180 : a;
    }

    /**
     * @param degrees the new azimuth
     * @return this camera turned to it
     */
    public Camera withAzimuth(double degrees) {
        return new Camera(degrees, elevation, zoom);
    }

    /**
     * @param degrees the new elevation, clamped to the allowed range
     * @return this camera raised or lowered to it
     */
    public Camera withElevation(double degrees) {
        return new Camera(azimuth, Math.max(MIN_ELEVATION, Math.min(90, degrees)), zoom);
    }

    /**
     * @param newZoom the new zoom, clamped to the allowed range
     * @return this camera at that zoom
     */
    public Camera withZoom(double newZoom) {
        return new Camera(azimuth, elevation, Math.max(MIN_ZOOM, Math.min(MAX_ZOOM, newZoom)));
    }

    /** @return the unit vector from the scene towards the camera, x, y, z */
    double[] towardsCamera() {
        return Light.direction(azimuth, elevation);
    }
}
