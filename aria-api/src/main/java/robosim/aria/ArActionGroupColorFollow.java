package robosim.aria;

/**
 * Following a colour, guarded, as ARIA 2.x's {@code ArActionGroupColorFollow} (ArActionGroups.cpp;
 * AriaCoda comments it out, with its {@code ArActionColorFollow} moved to the attic): ARIA's
 * table-sensor limiter (100), "Speed Limiter Near" (stop 300 mm, slow from 600 mm, 250 mm/s; 90),
 * "Speed Limiter Far" (300 mm, 1100 mm, 400 mm/s; 89), a backward limiter (80) and an
 * {@link ArActionColorFollow} "Follow a color." on the ACTS and camera given (70). Movement starts
 * stopped: {@link #startMovement()} lets it drive. Meant to be used one group at a time
 * ({@link #activateExclusive()}).
 */
public final class ArActionGroupColorFollow extends ArActionGroup {
    private final ArActionColorFollow colorFollow;

    /**
     * @param robot  the robot its actions are added to
     * @param acts   the ACTS whose blobs it follows
     * @param camera the camera it tilts, or null
     */
    public ArActionGroupColorFollow(ArRobot robot, ArACTS_1_2 acts, ArPTZ camera) {
        super(robot);
        addAction(new ArActionLimiterTableSensor(), 100);
        addAction(new ArActionLimiterForwards("Speed Limiter Near", 300, 600, 250), 90);
        addAction(new ArActionLimiterForwards("Speed Limiter Far", 300, 1100, 400), 89);
        addAction(new ArActionLimiterBackwards(), 80);
        colorFollow = new ArActionColorFollow("Follow a color.", acts, camera);
        addAction(colorFollow, 70);
    }

    /** @param channel the ACTS channel to follow, 1 to {@link ArACTS_1_2#NUM_CHANNELS} */
    public void setChannel(int channel) {
        colorFollow.setChannel(channel);
    }

    /** @param camera the camera it tilts */
    public void setCamera(ArPTZ camera) {
        colorFollow.setCamera(camera);
    }

    /** It drives after the blob. */
    public void startMovement() {
        colorFollow.startMovement();
    }

    /** It holds the robot still. */
    public void stopMovement() {
        colorFollow.stopMovement();
    }

    /** @param acquire whether, with no target, it turns to look for one */
    public void setAcquire(boolean acquire) {
        colorFollow.setAcquire(acquire);
    }

    /** @return the channel it follows */
    public int getChannel() {
        return colorFollow.getChannel();
    }

    /** @return whether it looks for a target when it has none */
    public boolean getAcquire() {
        return colorFollow.getAcquire();
    }

    /** @return whether it drives */
    public boolean getMovement() {
        return colorFollow.getMovement();
    }

    /** @return whether it has a target */
    public boolean getBlob() {
        return colorFollow.getBlob();
    }
}
