package robosim.viewer.view3d;

/**
 * Where the light comes from, for flat shading: a face is as bright as it faces the light. A
 * directional light, like the sun: one direction for the whole scene.
 *
 * @param azimuth   the compass direction towards the light, degrees counter-clockwise from +x
 * @param elevation the light's angle above the ground, degrees, from 0 to 90 (straight down)
 */
public record Light(double azimuth, double elevation) {
    /** From the south-west, 55° up. */
    public static final Light DEFAULT = new Light(-135, 55);

    /**
     * Checks the angles.
     *
     * @param azimuth   degrees, any finite value
     * @param elevation degrees, 0 to 90
     * @throws IllegalArgumentException naming the value and the rule it breaks
     */
    public Light {
        if (!Double.isFinite(azimuth)) {
            throw new IllegalArgumentException(azimuth + " was supplied for the light's azimuth: it must be a finite"
                    + " number of degrees");
        }
        if (!(elevation >= 0 && elevation <= 90)) {
            throw new IllegalArgumentException(elevation + " was supplied for the light's elevation: it must be"
                    + " from 0 to 90 degrees");
        }
    }

    /** @return the unit vector towards the light, x, y, z */
    double[] towardsLight() {
        return direction(azimuth, elevation);
    }

    static double[] direction(double azimuthDeg, double elevationDeg) {
        double a = Math.toRadians(azimuthDeg);
        double e = Math.toRadians(elevationDeg);
        return new double[] {Math.cos(e) * Math.cos(a), Math.cos(e) * Math.sin(a), Math.sin(e)};
    }
}
