package robosim.protocol;

/**
 * The pan-tilt-zoom cameras a robot may carry, with the limits, fields of view and speeds ARIA
 * gives them. Angles in degrees (pan positive to the right as ARIA's ArPTZ.h has it, tilt positive up), zoom in the
 * device's own units from {@link #minZoom()} (widest) to {@link #maxZoom()} (narrowest).
 */
public enum PtzModel {
    /**
     * The Canon VC-C4, as ARIA's ArVCC4.h and ArVCC4.cpp give it: pan ±98°, tilt −30° to 88°,
     * optical zoom 0 to 1960, a horizontal field of view of 45° at zoom 0 and 1.97° at 1960, and
     * top slew rates of 90 deg/s pan and 69 deg/s tilt.
     */
    VCC4(98, -98, 88, -30, 0, 1960, 45, 1.97, 90, 69),
    /**
     * The Sony EVI-D30, as ARIA 2.x's ArSonyPTZ gives it: pan ±95°, tilt ±25°, zoom 0 to 1023, a
     * horizontal field of view of 48.8° at zoom 0 and 4.4° at 1023. ARIA names no speed for it;
     * RoboSim moves it at the D30's top speeds of 80 deg/s pan and 50 deg/s tilt.
     */
    SONY(95, -95, 25, -25, 0, 1023, 48.8, 4.4, 80, 50);

    private final double maxPosPan;
    private final double maxNegPan;
    private final double maxPosTilt;
    private final double maxNegTilt;
    private final int minZoom;
    private final int maxZoom;
    private final double fovAtMinZoom;
    private final double fovAtMaxZoom;
    private final double panSpeed;
    private final double tiltSpeed;

    PtzModel(double maxPosPan, double maxNegPan, double maxPosTilt, double maxNegTilt, int minZoom, int maxZoom,
             double fovAtMinZoom, double fovAtMaxZoom, double panSpeed, double tiltSpeed) {
        this.maxPosPan = maxPosPan;
        this.maxNegPan = maxNegPan;
        this.maxPosTilt = maxPosTilt;
        this.maxNegTilt = maxNegTilt;
        this.minZoom = minZoom;
        this.maxZoom = maxZoom;
        this.fovAtMinZoom = fovAtMinZoom;
        this.fovAtMaxZoom = fovAtMaxZoom;
        this.panSpeed = panSpeed;
        this.tiltSpeed = tiltSpeed;
    }

    /** @return the farthest pan to the right, degrees */
    public double maxPosPan() {
        return maxPosPan;
    }

    /** @return the farthest pan to the left, degrees (negative) */
    public double maxNegPan() {
        return maxNegPan;
    }

    /** @return the highest tilt, degrees */
    public double maxPosTilt() {
        return maxPosTilt;
    }

    /** @return the lowest tilt, degrees (negative) */
    public double maxNegTilt() {
        return maxNegTilt;
    }

    /** @return the widest zoom */
    public int minZoom() {
        return minZoom;
    }

    /** @return the narrowest zoom */
    public int maxZoom() {
        return maxZoom;
    }

    /** @return the horizontal field of view at {@link #minZoom()}, degrees */
    public double fovAtMinZoom() {
        return fovAtMinZoom;
    }

    /** @return the horizontal field of view at {@link #maxZoom()}, degrees */
    public double fovAtMaxZoom() {
        return fovAtMaxZoom;
    }

    /** @return how fast it pans, deg/s */
    public double panSpeed() {
        return panSpeed;
    }

    /** @return how fast it tilts, deg/s */
    public double tiltSpeed() {
        return tiltSpeed;
    }

    /**
     * Clamps a pan into the limits, as ARIA's {@code ArVCC4::panTilt_i} does.
     *
     * @param pan degrees
     * @return the pan within [{@link #maxNegPan()}, {@link #maxPosPan()}]
     */
    public double clampPan(double pan) {
        return Math.max(maxNegPan, Math.min(maxPosPan, pan));
    }

    /**
     * Clamps a tilt into the limits, as ARIA's {@code ArVCC4::panTilt_i} does.
     *
     * @param tilt degrees
     * @return the tilt within [{@link #maxNegTilt()}, {@link #maxPosTilt()}]
     */
    public double clampTilt(double tilt) {
        return Math.max(maxNegTilt, Math.min(maxPosTilt, tilt));
    }

    /**
     * Clamps a zoom into the limits, as ARIA's {@code ArVCC4::zoom} does.
     *
     * @param zoom device units
     * @return the zoom within [{@link #minZoom()}, {@link #maxZoom()}]
     */
    public int clampZoom(int zoom) {
        return Math.max(minZoom, Math.min(maxZoom, zoom));
    }

    /**
     * The horizontal field of view at a zoom: the focal length grows linearly with the zoom from
     * the widest to the narrowest view (a lens's zoom moves its focal length), so the tangent of the
     * half angle is interpolated in its inverse.
     *
     * @param zoom device units, clamped into the limits
     * @return degrees, from {@link #fovAtMinZoom()} at the widest to {@link #fovAtMaxZoom()}
     */
    public double fieldOfView(int zoom) {
        double t = (clampZoom(zoom) - minZoom) / (double) (maxZoom - minZoom);
        double wide = 1 / Math.tan(Math.toRadians(fovAtMinZoom / 2));
        double narrow = 1 / Math.tan(Math.toRadians(fovAtMaxZoom / 2));
        double focal = wide + t * (narrow - wide);
        return 2 * Math.toDegrees(Math.atan(1 / focal));
    }
}
