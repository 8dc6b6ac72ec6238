package robosim.aria;

/**
 * Follows the largest colour blob an ACTS channel sees, as ARIA's {@code ArActionColorFollow}
 * (ARIA 2.x's ArActionColorFollow.cpp; AriaCoda keeps it in its attic): each firing it takes the
 * largest blob of more than 20 pixels on its channel. A blob seen within the last 2 s is a target:
 * the camera tilts a degree toward it when it is more than a fifth of the image off centre, and, with
 * movement started, the robot drives at the speed, turning by ten times the blob's horizontal offset
 * (as a fraction of the image width, so at most 10 degrees) when it is more than a tenth off centre.
 * A target not seen this cycle: turn 10 degrees toward the side it was last on (no velocity), or
 * drive on if it was centred. No target for 2 s: with acquiring on, the camera tilts level and the
 * robot turns in place 8 degrees a cycle to look for one. Otherwise, and with movement stopped (the
 * default), a velocity and a delta heading of 0.
 *
 * <p>The side names are ARIA's: a blob left of the image centre (negative offset) is recorded as
 * RIGHT and turned toward with a positive (leftward) delta heading.
 */
public class ArActionColorFollow extends ArAction {
    private enum Location { LEFT, RIGHT, CENTER }

    private final ArActionDesired desired = new ArActionDesired();
    private final ArACTS_1_2 acts;
    private ArPTZ camera;
    private final double speed;
    private final int width;
    private final int height;
    private final int maxTime = 2000;
    private final ArTime lastSeen = new ArTime();
    private boolean acquire = true;
    private boolean killMovement = true;
    private int channel;
    private boolean target;
    private Location location = Location.CENTER;

    /**
     * @param name   the action's name
     * @param acts   the ACTS whose blobs it follows, or null (then it holds the robot still)
     * @param camera the camera it tilts, or null
     */
    public ArActionColorFollow(String name, ArACTS_1_2 acts, ArPTZ camera) {
        this(name, acts, camera, 200);
    }

    /**
     * @param name   the action's name
     * @param acts   the ACTS whose blobs it follows
     * @param camera the camera it tilts, or null
     * @param speed  the speed it follows at, mm/s
     */
    public ArActionColorFollow(String name, ArACTS_1_2 acts, ArPTZ camera, double speed) {
        this(name, acts, camera, speed, 160);
    }

    /**
     * @param name   the action's name
     * @param acts   the ACTS whose blobs it follows
     * @param camera the camera it tilts, or null
     * @param speed  the speed it follows at, mm/s
     * @param width  the image's width, pixels
     */
    public ArActionColorFollow(String name, ArACTS_1_2 acts, ArPTZ camera, double speed, int width) {
        this(name, acts, camera, speed, width, 120);
    }

    /**
     * @param name   the action's name
     * @param acts   the ACTS whose blobs it follows
     * @param camera the camera it tilts, or null
     * @param speed  the speed it follows at, mm/s
     * @param width  the image's width, pixels (ARIA's default 160, as RoboSim's ACTS image)
     * @param height the image's height, pixels (ARIA's default 120)
     */
    public ArActionColorFollow(String name, ArACTS_1_2 acts, ArPTZ camera, double speed, int width, int height) {
        super(name, "Follows the largest blob of color.");
        this.acts = acts;
        this.camera = camera;
        this.speed = speed;
        this.width = width;
        this.height = height;
        setChannel(1);
    }

    @Override
    public synchronized ArActionDesired fire(ArActionDesired currentDesired) {
        desired.reset();
        ArACTSBlob largest = null;
        boolean moveFollowing = false;
        boolean moveAcquiring = false;
        if (acts != null) {
            int blobs = acts.getNumBlobs(channel);
            if (blobs > 0) {
                int area = 20;
                for (int i = 0; i < blobs; i++) {
                    ArACTSBlob blob = new ArACTSBlob();
                    acts.getBlob(channel, i + 1, blob);
                    if (blob.getArea() > area) {
                        area = blob.getArea();
                        largest = blob;
                    }
                }
                lastSeen.setToNow();
            }
            target = lastSeen.mSecSince() <= maxTime;
            moveFollowing = target;
            moveAcquiring = !target && acquire;
        } else {
            target = false;
        }
        if (moveFollowing) {
            if (largest != null) {
                double xRel = (largest.getXCG() - width / 2.0) / width;
                double yRel = (largest.getYCG() - height / 2.0) / height;
                if (!(Math.abs(yRel) < .20) && camera != null) {
                    camera.tiltRel(-yRel > 0 ? 1 : -1);
                }
                if (!killMovement) {
                    if (Math.abs(xRel) < .10) {
                        location = Location.CENTER;
                        desired.setDeltaHeading(0);
                    } else if (Math.abs(-xRel * 10) <= 10) {
                        location = xRel < 0 ? Location.RIGHT : Location.LEFT;
                        desired.setDeltaHeading(-xRel * 10);
                    } else if (-xRel > 0) {
                        location = Location.RIGHT;
                        desired.setDeltaHeading(10);
                    } else {
                        location = Location.LEFT;
                        desired.setDeltaHeading(-10);
                    }
                    desired.setVel(speed);
                    return desired;
                }
            } else if (!killMovement) {
                switch (location) {
                    case LEFT -> {
                        desired.setDeltaHeading(-10);
                        desired.setVel(0);
                    }
                    case RIGHT -> {
                        desired.setDeltaHeading(10);
                        desired.setVel(0);
                    }
                    default -> {
                        desired.setDeltaHeading(0);
                        desired.setVel(speed);
                    }
                }
                return desired;
            }
        } else if (moveAcquiring) {
            if (camera != null) {
                camera.tilt(0);
            }
            if (!killMovement) {
                desired.setVel(0);
                desired.setDeltaHeading(8);
                return desired;
            }
        }
        desired.setVel(0);
        desired.setDeltaHeading(0);
        return desired;
    }

    /**
     * @param channel the ACTS channel to follow, 1 to {@link ArACTS_1_2#NUM_CHANNELS}
     * @return false (and no change) for a channel outside that
     */
    public synchronized boolean setChannel(int channel) {
        if (channel >= 1 && channel <= ArACTS_1_2.NUM_CHANNELS) {
            this.channel = channel;
            return true;
        }
        return false;
    }

    /** @param camera the camera it tilts, or null */
    public synchronized void setCamera(ArPTZ camera) {
        this.camera = camera;
    }

    /** @param acquire whether, with no target, it turns to look for one */
    public synchronized void setAcquire(boolean acquire) {
        this.acquire = acquire;
    }

    /** It holds the robot still (the default); the camera still tilts. */
    public synchronized void stopMovement() {
        killMovement = true;
    }

    /** It drives after the blob. */
    public synchronized void startMovement() {
        killMovement = false;
    }

    /** @return the channel it follows */
    public synchronized int getChannel() {
        return channel;
    }

    /** @return whether it looks for a target when it has none */
    public synchronized boolean getAcquire() {
        return acquire;
    }

    /** @return whether it drives */
    public synchronized boolean getMovement() {
        return !killMovement;
    }

    /** @return whether it has a target (a blob seen within 2 s, at the last firing) */
    public synchronized boolean getBlob() {
        return target;
    }

    @Override
    public synchronized ArActionDesired getDesired() {
        return desired;
    }
}
