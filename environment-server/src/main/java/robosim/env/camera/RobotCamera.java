package robosim.env.camera;

import java.util.Arrays;
import java.util.List;
import robosim.protocol.CameraView;
import robosim.protocol.Colors;
import robosim.protocol.Command;
import robosim.protocol.PtzModel;

/**
 * One robot's pan-tilt-zoom camera and its ACTS colour tracking: switched on by
 * {@link Command.ConfigurePtz} or {@link Command.TrackColors}, pointed by {@link Command.AimPtz},
 * its channels bound by {@link Command.BindChannel}. Until a robot switches it on it costs nothing
 * and reports nothing.
 *
 * <p>The channels start bound to {@link #DEFAULT_CHANNELS}: channel 1 red, 2 green, 3 blue,
 * 4 yellow, 5 cyan, 6 magenta, 7 orange, 8 purple; channels 9 to 32 are free.
 */
public final class RobotCamera {
    /** The lens's height when the robot does not give one, mm: a VC-C4 on a Pioneer 3-DX's top plate. */
    public static final double DEFAULT_MOUNT_HEIGHT = 300;
    /** The colours channels 1 to 8 start bound to. */
    public static final List<String> DEFAULT_CHANNELS =
            List.of("red", "green", "blue", "yellow", "cyan", "magenta", "orange", "purple");

    private static final int[] DEFAULT_RGB = defaultRgb();

    private PtzMotion ptz;
    private double mountHeight = DEFAULT_MOUNT_HEIGHT;
    private boolean tracking;
    private final int[] channels = new int[CameraView.CHANNELS];
    private CameraView view;

    /** A camera switched off, its channels at their defaults. */
    public RobotCamera() {
        System.arraycopy(DEFAULT_RGB, 0, channels, 0, channels.length);
    }

    private static int[] defaultRgb() {
        int[] rgb = new int[CameraView.CHANNELS];
        Arrays.fill(rgb, ColoredShape.NO_COLOR);
        for (int i = 0; i < DEFAULT_CHANNELS.size(); i++) {
            rgb[i] = Colors.parse(DEFAULT_CHANNELS.get(i));
        }
        return rgb;
    }

    /**
     * @param c a sensor setting
     * @return whether it is the camera's: {@link Command.ConfigurePtz}, {@link Command.AimPtz},
     *         {@link Command.TrackColors} or {@link Command.BindChannel}
     */
    public static boolean handles(Command.SensorSetting c) {
        return c instanceof Command.ConfigurePtz || c instanceof Command.AimPtz
                || c instanceof Command.TrackColors || c instanceof Command.BindChannel;
    }

    /**
     * Carries out one of the camera's settings. Pointing a camera that is not on switches on a
     * VC-C4 at the default height first, as does tracking colours.
     *
     * @param c a setting {@link #handles} accepts
     */
    public void configure(Command.SensorSetting c) {
        if (c instanceof Command.ConfigurePtz p) {
            ptz = new PtzMotion(p.model());
            mountHeight = p.mountHeight();
        } else if (c instanceof Command.AimPtz a) {
            on().aim(a.pan(), a.tilt(), a.zoom());
        } else if (c instanceof Command.TrackColors t) {
            tracking = t.on();
            if (tracking) {
                on();
            }
        } else if (c instanceof Command.BindChannel b) {
            channels[b.channel() - 1] = b.color() == null ? ColoredShape.NO_COLOR : Colors.parse(b.color());
        } else {
            throw new IllegalStateException("the camera has no rule for " + c);
        }
    }

    private PtzMotion on() {
        if (ptz == null) {
            ptz = new PtzMotion(PtzModel.VCC4);
        }
        return ptz;
    }

    /** @return whether the robot has switched the camera on */
    public boolean isOn() {
        return ptz != null;
    }

    /**
     * Moves the camera for a step and, while tracking, finds the blobs it sees from the robot's
     * true pose. Does nothing while the camera is off.
     *
     * @param x       the robot's x, mm
     * @param y       the robot's y, mm
     * @param thDeg   the robot's heading, degrees; the camera looks at the heading minus its pan
     * @param dt      seconds the camera moves for (0 for a reading before the first step)
     * @param shapes  what there is to see
     * @param ownBody the robot's own body, which its camera does not see
     */
    public void read(double x, double y, double thDeg, double dt, List<ColoredShape> shapes, int ownBody) {
        if (ptz == null) {
            return;
        }
        ptz.advance(dt);
        List<robosim.protocol.ColorBlob> blobs = List.of();
        if (tracking) {
            double fov = Math.toRadians(ptz.model().fieldOfView(ptz.zoom()));
            int[] image = CameraImage.render(x, y, mountHeight, Math.toRadians(thDeg - ptz.pan()),
                    Math.toRadians(ptz.tilt()), fov, shapes, ownBody);
            blobs = BlobFinder.find(image, channels);
        }
        view = new CameraView(ptz.model(), ptz.pan(), ptz.tilt(), ptz.zoom(), blobs);
    }

    /** @return the latest view, or null while the camera is off */
    public CameraView view() {
        return ptz == null ? null : view == null ? new CameraView(ptz.model(), ptz.pan(), ptz.tilt(), ptz.zoom(),
                List.of()) : view;
    }
}
