package robosim.examples.colorfollower;

import robosim.aria.ArACTSBlob;
import robosim.aria.ArACTS_1_2;
import robosim.aria.ArRobot;
import robosim.aria.ArUtil;
import robosim.aria.ArVCC4;

/**
 * ARIA's {@code actsColorFollowingExample}: a Pioneer with a VC-C4 camera and ACTS chases the
 * largest blob of one channel (red, channel 1, unless told otherwise). Each step it takes the
 * largest blob of more than 10 pixels; while it has seen one within the last second it turns by
 * up to 10° towards it (none when the blob is within a tenth of the image's width of the centre),
 * tilts the camera a degree towards it when it is more than a fifth of the image's height off
 * centre, and drives at 200 mm/s. Two of the original's speed limiters slow it by its front sonars
 * (stop at 350 mm and 400 mm, slowing from 800 mm and 1250 mm), so it stops before the thing it
 * chases; with no target it stands still. ARIA's example runs this as an action ({@code Chase})
 * among limiter actions; here it is one decision per step, measured in simulated time.
 *
 * <p>Run it as {@code bin/robosim robot robosim.examples.colorfollower.ColorFollower NAME HOST PORT [CHANNEL]}.
 */
public final class ColorFollower {
    /** The speed it chases at, mm/s, as the original's {@code setVel(200)}. */
    public static final int CHASE_SPEED = 200;
    /** A blob must be larger than this, pixels, as the original's {@code blobArea}. */
    public static final int MIN_AREA = 10;
    /** How long a target is kept after it was last seen, simulated ms (the original's {@code myMaxTime}). */
    public static final long TARGET_KEPT_MS = 1000;

    private final ArRobot robot;
    private final ArVCC4 camera;
    private final ArACTS_1_2 acts = new ArACTS_1_2();
    private final int channel;
    private long lastSeenMs = Long.MIN_VALUE / 2;

    /**
     * @param robot   a robot that is not connected yet
     * @param channel the ACTS channel to chase, 1 to 32
     * @throws IllegalArgumentException if the channel is outside 1 to 32
     */
    public ColorFollower(ArRobot robot, int channel) {
        if (channel < 1 || channel > ArACTS_1_2.NUM_CHANNELS) {
            throw new IllegalArgumentException(channel + " was supplied for the channel: ACTS has channels 1 to "
                    + ArACTS_1_2.NUM_CHANNELS);
        }
        this.robot = robot;
        this.camera = new ArVCC4(robot);
        this.channel = channel;
    }

    /**
     * Chases the largest blob until the Environment ends the run.
     *
     * @param args NAME HOST PORT [CHANNEL]
     */
    public static void main(String[] args) {
        if (args.length != 3 && args.length != 4) {
            throw new IllegalArgumentException("usage: ColorFollower NAME HOST PORT [CHANNEL]");
        }
        ColorFollower follower = new ColorFollower(new ArRobot(args[0], args[1], Integer.parseInt(args[2]), "p3dx"),
                args.length == 4 ? Integer.parseInt(args[3]) : 1);
        follower.connect();
        follower.run();
    }

    /**
     * Connects the robot, switches the camera on and opens ACTS, as the original's {@code main}.
     *
     * @throws IllegalStateException if the robot cannot connect, with the reason
     */
    public void connect() {
        if (!robot.blockingConnect()) {
            throw new IllegalStateException("robot " + robot.getName() + " could not connect: "
                    + robot.getConnectionError());
        }
        robot.enableMotors();
        acts.openPort(robot);
        camera.init();
    }

    /** Chases, one decision per step, until the robot is disconnected. */
    public void run() {
        while (robot.isConnected()) {
            decide();
            ArUtil.sleep(robot.getStepMs());
        }
    }

    /** One step's decision, from the latest blobs. */
    void decide() {
        ArACTSBlob largest = largestBlob();
        if (largest != null) {
            lastSeenMs = robot.getSimTimeMs();
        }
        boolean target = robot.getSimTimeMs() - lastSeenMs <= TARGET_KEPT_MS;
        if (!target || largest == null) {
            // the original leaves the robot to its lowest action then: a constant velocity of 0
            robot.setVel(0);
            robot.setRotVel(0);
            return;
        }
        double xRel = (largest.getXCG() - ArACTS_1_2.WIDTH / 2.0) / ArACTS_1_2.WIDTH;
        double yRel = (largest.getYCG() - ArACTS_1_2.HEIGHT / 2.0) / ArACTS_1_2.HEIGHT;
        if (Math.abs(yRel) >= 0.20) {
            camera.tiltRel(-yRel > 0 ? 1 : -1);
        }
        double turn = Math.abs(xRel) < 0.10 ? 0 : Math.max(-10, Math.min(10, -xRel * 10));
        robot.setDeltaHeading(turn);
        robot.setVel(Math.min(CHASE_SPEED, limit()));
    }

    /** @return the largest blob of the channel over {@link #MIN_AREA} pixels, or null */
    private ArACTSBlob largestBlob() {
        ArACTSBlob largest = null;
        int area = MIN_AREA;
        int n = acts.getNumBlobs(channel);
        for (int i = 1; i <= n; i++) {
            ArACTSBlob blob = new ArACTSBlob();
            if (acts.getBlob(channel, i, blob) && blob.getArea() > area) {
                area = blob.getArea();
                largest = blob;
            }
        }
        return largest;
    }

    /**
     * The original's two forward limiters, {@code ArActionLimiterForwards("speed limiter near", 350,
     * 800, 200)} and {@code ("speed limiter far", 400, 1250, 300)}, on the front sonars: each allows
     * nothing nearer than its stop distance and a speed growing linearly to its slow speed at its
     * slow distance, as ArActionLimiterForwards.cpp does.
     *
     * @return the fastest forward speed the limiters allow, mm/s
     */
    private double limit() {
        int front = robot.getClosestSonarRange(-20, 20);
        if (front < 0) {
            return CHASE_SPEED;
        }
        return Math.min(limiter(front, 350, 800, 200), limiter(front, 400, 1250, 300));
    }

    private static double limiter(double dist, double stop, double slow, double slowSpeed) {
        if (dist < stop) {
            return 0;
        }
        return dist > slow ? Double.MAX_VALUE : slowSpeed * (dist - stop) / (slow - stop);
    }
}
