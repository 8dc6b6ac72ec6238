package robosim.aria;

import java.util.ArrayList;
import java.util.List;
import robosim.protocol.CameraView;
import robosim.protocol.ColorBlob;
import robosim.protocol.Command;
import robosim.protocol.RobotState;

/**
 * ACTS colour-blob tracking with ARIA's {@code ArACTS_1_2} names (ArACTS.h): channels 1 to
 * {@value #NUM_CHANNELS}, blobs numbered from 1, largest first, at most {@value #MAX_BLOBS} a
 * channel, in a {@value #WIDTH} × {@value #HEIGHT} image. The Environment computes the blobs each
 * step from what the robot's camera sees (see the camera model in docs/SIMULATION.md), so there is no ACTS
 * server to reach: {@link #openPort(ArRobot)} starts the tracking.
 *
 * <p>The channels start bound to red (1), green (2), blue (3), yellow (4), cyan (5), magenta (6),
 * orange (7) and purple (8); {@link #setChannelColor} binds a channel to another colour (what
 * training ACTS on a colour does), or frees it.
 *
 * <pre>{@code
 * ArACTS_1_2 acts = new ArACTS_1_2();
 * acts.openPort(robot);
 * ArACTSBlob blob = new ArACTSBlob();
 * if (acts.getNumBlobs(1) > 0 && acts.getBlob(1, 1, blob)) { ... blob.getXCG() ... }
 * }</pre>
 */
public final class ArACTS_1_2 {
    /** ACTS's channels. */
    public static final int NUM_CHANNELS = CameraView.CHANNELS;
    /** The most blobs a channel reports. */
    public static final int MAX_BLOBS = CameraView.MAX_BLOBS;
    /** The image's width, pixels. */
    public static final int WIDTH = CameraView.IMAGE_WIDTH;
    /** The image's height, pixels. */
    public static final int HEIGHT = CameraView.IMAGE_HEIGHT;

    private volatile ArRobot robot;
    private volatile boolean inverted;
    private volatile int width = WIDTH;
    private volatile int height = HEIGHT;

    /**
     * Starts tracking colours on a robot's camera (ARIA's {@code openPort}; the host and port of
     * an ACTS server have no meaning here). A robot whose camera is not on gets a VC-C4 pointing
     * straight ahead.
     *
     * @param robot the robot
     * @return true: the request goes with the next step's requests
     */
    public boolean openPort(ArRobot robot) {
        if (robot == null) {
            throw new IllegalArgumentException("ACTS needs the robot whose camera it reads");
        }
        this.robot = robot;
        robot.send(new Command.TrackColors(true));
        return true;
    }

    /** @return true if it was tracking; it stops */
    public boolean closePort() {
        ArRobot r = robot;
        if (r == null) {
            return false;
        }
        r.send(new Command.TrackColors(false));
        robot = null;
        return true;
    }

    /** @return whether {@link #openPort} has been called and not closed */
    public boolean isConnected() {
        return robot != null;
    }

    /** @return the robot, or null */
    public ArRobot getRobot() {
        return robot;
    }

    /**
     * Binds a channel to a colour, or frees it (a RoboSim addition standing for training ACTS).
     *
     * @param channel 1 to {@value #NUM_CHANNELS}
     * @param color   a colour's name such as {@code red}, or {@code #rrggbb}; null frees the channel
     * @throws IllegalArgumentException if the channel or the colour breaks its rule, or ACTS is not open
     */
    public void setChannelColor(int channel, String color) {
        Command.BindChannel bind = new Command.BindChannel(channel, color);
        ArRobot r = robot;
        if (r == null) {
            throw new IllegalArgumentException("ACTS is not open: call openPort(robot) before binding channel "
                    + channel);
        }
        r.send(bind);
    }

    /**
     * Flips the image's stats for a camera mounted upside down, as ARIA's ArACTS.cpp does: each x
     * becomes the width minus x and each y the height minus y, the left and right (top and bottom)
     * borders each flipped in place.
     */
    public void invert() {
        invert(WIDTH, HEIGHT);
    }

    /**
     * {@link #invert()} for an image of another size (ARIA's {@code invert(width, height)}; ARIA's
     * own sets both to 1 by a slip, RoboSim uses the values given).
     *
     * @param width  the image's width, pixels
     * @param height the image's height, pixels
     */
    public void invert(int width, int height) {
        this.width = width;
        this.height = height;
        inverted = true;
    }

    /**
     * @param channel 1 to {@value #NUM_CHANNELS}
     * @return the blobs the channel sees now; −1 for a channel outside 1 to {@value #NUM_CHANNELS},
     *         as ARIA's ArACTS.cpp answers
     */
    public int getNumBlobs(int channel) {
        if (channel < 1 || channel > NUM_CHANNELS) {
            return -1;
        }
        return blobs(channel).size();
    }

    /**
     * Fills in a blob, as ARIA's {@code getBlob}.
     *
     * @param channel    1 to {@value #NUM_CHANNELS}
     * @param blobNumber 1 for the largest, up to {@link #getNumBlobs}
     * @param blob       filled in when there is such a blob
     * @return false for a channel or number with no blob (nothing is filled in)
     */
    public boolean getBlob(int channel, int blobNumber, ArACTSBlob blob) {
        if (channel < 1 || channel > NUM_CHANNELS) {
            return false;
        }
        List<ColorBlob> list = blobs(channel);
        if (blobNumber < 1 || blobNumber > list.size()) {
            return false;
        }
        ColorBlob b = list.get(blobNumber - 1);
        blob.setArea(b.area());
        blob.setXCG(x(b.xcg()));
        blob.setYCG(y(b.ycg()));
        blob.setLeft(x(b.left()));
        blob.setRight(x(b.right()));
        blob.setTop(y(b.top()));
        blob.setBottom(y(b.bottom()));
        return true;
    }

    private int x(int column) {
        return inverted ? width - column : column;
    }

    private int y(int row) {
        return inverted ? height - row : row;
    }

    private List<ColorBlob> blobs(int channel) {
        ArRobot r = robot;
        RobotState s = r == null ? null : r.currentState();
        CameraView v = s == null ? null : s.get(CameraView.PART);
        List<ColorBlob> out = new ArrayList<>();
        if (v != null) {
            for (ColorBlob b : v.blobs()) {
                if (b.channel() == channel) {
                    out.add(b);
                }
            }
        }
        return out;
    }
}
