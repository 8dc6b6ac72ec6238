package robosim.env.camera;

import robosim.protocol.PtzModel;

/**
 * Where a pan-tilt-zoom camera points and where it was told to: each step it moves towards the
 * target at its model's pan and tilt speeds. The zoom, which ARIA gives no speed for, reaches its
 * target within the step. Targets are clamped into the model's limits as ARIA's ArVCC4.cpp clamps
 * them.
 */
public final class PtzMotion {
    private final PtzModel model;
    private double pan;
    private double tilt;
    private int zoom;
    private double panTarget;
    private double tiltTarget;
    private int zoomTarget;

    /** @param model the camera, at pan 0, tilt 0 and its widest zoom */
    public PtzMotion(PtzModel model) {
        this.model = model;
        this.zoom = model.minZoom();
        this.zoomTarget = zoom;
    }

    /**
     * Sets the target, clamped into the limits.
     *
     * @param pan  degrees
     * @param tilt degrees
     * @param zoom zoom units
     */
    public void aim(double pan, double tilt, int zoom) {
        panTarget = model.clampPan(pan);
        tiltTarget = model.clampTilt(tilt);
        zoomTarget = model.clampZoom(zoom);
    }

    /**
     * Moves towards the target for {@code dt} seconds.
     *
     * @param dt seconds, 0 or more
     */
    public void advance(double dt) {
        pan = toward(pan, panTarget, model.panSpeed() * dt);
        tilt = toward(tilt, tiltTarget, model.tiltSpeed() * dt);
        zoom = zoomTarget;
    }

    private static double toward(double from, double to, double most) {
        return from + Math.max(-most, Math.min(most, to - from));
    }

    /** @return the camera */
    public PtzModel model() {
        return model;
    }

    /** @return degrees, positive to the right */
    public double pan() {
        return pan;
    }

    /** @return degrees, positive up */
    public double tilt() {
        return tilt;
    }

    /** @return zoom units */
    public int zoom() {
        return zoom;
    }
}
