package robosim.aria;

import robosim.protocol.CameraView;
import robosim.protocol.Command;
import robosim.protocol.PtzModel;
import robosim.protocol.RobotState;

/**
 * A pan-tilt-zoom camera on a robot, with ARIA's {@code ArPTZ} names (ArPTZ.h): pan 0 straight
 * ahead, negative to the left and positive to the right; tilt positive up; zoom in the camera's own
 * units. Commands beyond the limits are clamped as ARIA's ArVCC4.cpp clamps them, and relative
 * moves count from the last position asked for, as ARIA's do. The camera moves at its own speed:
 * {@link #getPan()}, {@link #getTilt()} and {@link #getZoom()} answer where the Environment last
 * reported it (the position a real camera reports back), or where it was told to go before the
 * first report.
 *
 * <pre>{@code
 * ArVCC4 ptz = new ArVCC4(robot);
 * ptz.init();            // switched on with the next step's requests
 * ptz.panTilt(30, -10);  // moves there at 90 deg/s and 69 deg/s
 * }</pre>
 */
public abstract class ArPTZ {
    /** The lens's height when none is set, mm (see {@link #setMountHeight}). */
    public static final double DEFAULT_MOUNT_HEIGHT = 300;

    private final ArRobot robot;
    private final PtzModel model;
    private volatile double mountHeight = DEFAULT_MOUNT_HEIGHT;
    private volatile double panDesired;
    private volatile double tiltDesired;
    private volatile int zoomDesired;

    /**
     * @param robot the robot that carries it
     * @param model the camera
     */
    protected ArPTZ(ArRobot robot, PtzModel model) {
        if (robot == null) {
            throw new IllegalArgumentException("a camera needs the robot that carries it");
        }
        this.robot = robot;
        this.model = model;
        this.zoomDesired = model.minZoom();
    }

    /**
     * Switches the camera on at pan 0, tilt 0 and its widest zoom (ARIA's {@code init}).
     *
     * @return true: the request goes with the next step's requests
     */
    public boolean init() {
        panDesired = 0;
        tiltDesired = 0;
        zoomDesired = model.minZoom();
        robot.send(new Command.ConfigurePtz(model, mountHeight));
        return true;
    }

    /** @return the name of this camera type, as ARIA's {@code getTypeName} */
    public abstract String getTypeName();

    /**
     * Sets how high the lens stands above the floor, before {@link #init} (a RoboSim addition: ARIA's
     * parameter files name no camera height). The camera sits at the robot's centre.
     *
     * @param mm greater than 0; {@value #DEFAULT_MOUNT_HEIGHT} unless set
     * @throws IllegalArgumentException if it is not a finite number greater than 0
     */
    public void setMountHeight(double mm) {
        if (!(Double.isFinite(mm) && mm > 0)) {
            throw new IllegalArgumentException(mm + " was supplied for the camera's mount height: it must be greater than 0");
        }
        mountHeight = mm;
    }

    /** Back to pan 0, tilt 0 and the widest zoom, as ARIA's {@code reset}. */
    public void reset() {
        panTilt(0, 0);
        zoom(getMinZoom());
    }

    /**
     * @param degrees where to pan, 0 ahead, negative to the left; clamped into the limits
     * @return true
     */
    public boolean pan(double degrees) {
        return panTilt(degrees, tiltDesired);
    }

    /**
     * @param degrees how far to pan from the last pan asked for
     * @return true
     */
    public boolean panRel(double degrees) {
        return panTilt(panDesired + degrees, tiltDesired);
    }

    /**
     * @param degrees where to tilt, positive up; clamped into the limits
     * @return true
     */
    public boolean tilt(double degrees) {
        return panTilt(panDesired, degrees);
    }

    /**
     * @param degrees how far to tilt from the last tilt asked for
     * @return true
     */
    public boolean tiltRel(double degrees) {
        return panTilt(panDesired, tiltDesired + degrees);
    }

    /**
     * Pans and tilts at once, each clamped into its limits as ARIA's {@code ArVCC4::panTilt_i} does.
     *
     * @param degreesPan  where to pan
     * @param degreesTilt where to tilt
     * @return true
     * @throws IllegalArgumentException if either is not finite
     */
    public boolean panTilt(double degreesPan, double degreesTilt) {
        Command.AimPtz checked = new Command.AimPtz(degreesPan, degreesTilt, zoomDesired);
        panDesired = model.clampPan(checked.pan());
        tiltDesired = model.clampTilt(checked.tilt());
        return aim();
    }

    /**
     * @param degreesPan  how far to pan from the last pan asked for
     * @param degreesTilt how far to tilt from the last tilt asked for
     * @return true
     */
    public boolean panTiltRel(double degreesPan, double degreesTilt) {
        return panTilt(panDesired + degreesPan, tiltDesired + degreesTilt);
    }

    /** @return true: both cameras zoom */
    public boolean canZoom() {
        return true;
    }

    /**
     * @param zoomValue where to zoom, clamped into [{@link #getMinZoom()}, {@link #getMaxZoom()}]
     * @return true
     */
    public boolean zoom(int zoomValue) {
        zoomDesired = model.clampZoom(zoomValue);
        return aim();
    }

    /**
     * @param zoomValue how far to zoom from the last zoom asked for
     * @return true
     */
    public boolean zoomRel(int zoomValue) {
        return zoom(zoomDesired + zoomValue);
    }

    private boolean aim() {
        robot.send(new Command.AimPtz(panDesired, tiltDesired, zoomDesired));
        return true;
    }

    private CameraView view() {
        RobotState s = robot.currentState();
        return s == null ? null : s.get(CameraView.PART);
    }

    /** @return the pan the Environment last reported, degrees; the pan asked for before any report */
    public double getPan() {
        CameraView v = view();
        return v == null ? panDesired : v.pan();
    }

    /** @return the tilt the Environment last reported, degrees; the tilt asked for before any report */
    public double getTilt() {
        CameraView v = view();
        return v == null ? tiltDesired : v.tilt();
    }

    /** @return the zoom the Environment last reported; the zoom asked for before any report */
    public int getZoom() {
        CameraView v = view();
        return v == null ? zoomDesired : v.zoom();
    }

    /** @return the pan last asked for, within the limits, degrees */
    public double getPanDesired() {
        return panDesired;
    }

    /** @return the tilt last asked for, within the limits, degrees */
    public double getTiltDesired() {
        return tiltDesired;
    }

    /** @return the farthest pan to the right, degrees */
    public double getMaxPosPan() {
        return model.maxPosPan();
    }

    /** @return the farthest pan to the left, degrees (negative) */
    public double getMaxNegPan() {
        return model.maxNegPan();
    }

    /** @return ARIA's other name for {@link #getMaxPosPan()} */
    public double getMaxPan() {
        return getMaxPosPan();
    }

    /** @return ARIA's other name for {@link #getMaxNegPan()} */
    public double getMinPan() {
        return getMaxNegPan();
    }

    /** @return the highest tilt, degrees */
    public double getMaxPosTilt() {
        return model.maxPosTilt();
    }

    /** @return the lowest tilt, degrees (negative) */
    public double getMaxNegTilt() {
        return model.maxNegTilt();
    }

    /** @return ARIA's other name for {@link #getMaxPosTilt()} */
    public double getMaxTilt() {
        return getMaxPosTilt();
    }

    /** @return ARIA's other name for {@link #getMaxNegTilt()} */
    public double getMinTilt() {
        return getMaxNegTilt();
    }

    /** @return the narrowest zoom */
    public int getMaxZoom() {
        return model.maxZoom();
    }

    /** @return the widest zoom */
    public int getMinZoom() {
        return model.minZoom();
    }

    /** @return true: both cameras know their field of view */
    public boolean canGetFOV() {
        return true;
    }

    /** @return the horizontal field of view at the narrowest zoom, degrees */
    public double getFOVAtMaxZoom() {
        return model.fovAtMaxZoom();
    }

    /** @return the horizontal field of view at the widest zoom, degrees */
    public double getFOVAtMinZoom() {
        return model.fovAtMinZoom();
    }

    /** @return the horizontal field of view at the reported zoom, degrees (a RoboSim addition) */
    public double getFOV() {
        return model.fieldOfView(getZoom());
    }

    /** @return how fast it pans, deg/s */
    public double getMaxPanSpeed() {
        return model.panSpeed();
    }

    /** @return how fast it tilts, deg/s */
    public double getMaxTiltSpeed() {
        return model.tiltSpeed();
    }

    /** @return the robot that carries it */
    public ArRobot getRobot() {
        return robot;
    }

    /** @return the camera model, which gives its limits */
    public PtzModel getModel() {
        return model;
    }
}
