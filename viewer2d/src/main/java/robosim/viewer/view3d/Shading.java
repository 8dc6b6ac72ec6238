package robosim.viewer.view3d;

import java.awt.Color;

/**
 * Flat shading: a face's colour is its base colour times its brightness, the ambient share plus
 * the diffuse share times the cosine between its normal and the direction to the light (none when
 * it faces away). Faces turned from the light keep only the ambient share, so they are darker.
 */
public final class Shading {
    /** The share of light every face gets. */
    public static final double AMBIENT = 0.4;
    /** The share a face gets when it faces the light squarely. */
    public static final double DIFFUSE = 0.6;

    private Shading() {
    }

    /**
     * @param base         the face's colour
     * @param normal       its outward unit normal
     * @param towardsLight the unit vector towards the light
     * @return the face's shaded colour
     */
    static Color shade(Color base, double[] normal, double[] towardsLight) {
        double cos = normal[0] * towardsLight[0] + normal[1] * towardsLight[1] + normal[2] * towardsLight[2];
        double b = brightness(cos);
        return new Color(channel(base.getRed(), b), channel(base.getGreen(), b), channel(base.getBlue(), b));
    }

    /**
     * @param cosine the cosine between a face's normal and the direction to the light
     * @return its brightness, {@link #AMBIENT} to 1
     */
    public static double brightness(double cosine) {
        return AMBIENT + DIFFUSE * Math.max(0, cosine);
    }

    private static int channel(int value, double brightness) {
        return (int) Math.max(0, Math.min(255, Math.round(value * brightness)));
    }
}
