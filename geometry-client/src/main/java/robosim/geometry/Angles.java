package robosim.geometry;

/** Angle helpers in ARIA's convention: degrees, normalised to (-180, 180]. */
public final class Angles {
    private Angles() {
    }

    /**
     * ARIA's {@code ArMath::fixAngle}.
     *
     * @param degrees any angle
     * @return the same direction in (-180, 180]
     */
    public static double fix(double degrees) {
        double a = Math.IEEEremainder(degrees, 360.0);
        return a <= -180.0 ? a + 360.0 : a;
    }
}
