package robosim.remote;

import java.util.EnumMap;
import java.util.EnumSet;
import java.util.Map;
import java.util.Set;

/**
 * Hold-to-drive from the arrow keys, with the feel of ARIA's keyboard teleop: while up or down is
 * held the robot goes forward or back at the translational speed, while left or right is held it
 * turns at the rotational speed (ARIA's {@code ArRatioInputKeydrive} also turns only while the key
 * is held); when the last key is released it stops. Both can be held: up and left drive an arc.
 *
 * <p>A release counts only after {@value #RELEASE_GRACE_MS} ms without the key pressed again: on
 * X11, Java reports a held key's auto-repeat as release and press pairs, which would otherwise stop
 * and restart the robot every repeat. Time comes in as an argument, so this is tested without a
 * clock.
 */
public final class KeyDrive {
    /** How long a released key still counts as held, ms. */
    public static final long RELEASE_GRACE_MS = 100;

    /** The four driving keys. */
    public enum Key {
        /** Up arrow: forward. */
        FORWARD,
        /** Down arrow: back. */
        BACK,
        /** Left arrow: turn counter-clockwise. */
        LEFT,
        /** Right arrow: turn clockwise. */
        RIGHT
    }

    /**
     * What the keys held ask for.
     *
     * @param vel    mm/s
     * @param rotVel deg/s
     */
    public record Drive(double vel, double rotVel) {
        /** @return whether this is standing still */
        public boolean isStop() {
            return vel == 0 && rotVel == 0;
        }
    }

    private final Set<Key> held = EnumSet.noneOf(Key.class);
    private final Map<Key, Long> releasedAt = new EnumMap<>(Key.class);

    /**
     * @param key the key pressed (again, when auto-repeat presses it)
     * @param nowMs the time, ms
     * @return true if this starts holding a key not held before: the drive changed
     */
    public boolean press(Key key, long nowMs) {
        releasedAt.remove(key);
        return held.add(key);
    }

    /**
     * @param key   the key released; it stops counting after the grace time (see {@link #due})
     * @param nowMs the time, ms
     */
    public void release(Key key, long nowMs) {
        if (held.contains(key)) {
            releasedAt.put(key, nowMs);
        }
    }

    /**
     * Lets go of the keys released at least the grace time ago.
     *
     * @param nowMs the time, ms
     * @return true if a key was let go: the drive changed
     */
    public boolean due(long nowMs) {
        boolean changed = releasedAt.entrySet().removeIf(e -> nowMs - e.getValue() >= RELEASE_GRACE_MS
                && held.remove(e.getKey()));
        return changed;
    }

    /** Lets go of every key at once (the stop button, the space bar, the window losing focus). */
    public void clear() {
        held.clear();
        releasedAt.clear();
    }

    /** @return whether any key is held */
    public boolean anyHeld() {
        return !held.isEmpty();
    }

    /** @return whether a key is waiting out its grace time */
    public boolean releasePending() {
        return !releasedAt.isEmpty();
    }

    /**
     * @param vel    the translational speed, mm/s, at least 0
     * @param rotVel the rotational speed, deg/s, at least 0
     * @return what the keys held ask for: opposite keys cancel
     */
    public Drive drive(double vel, double rotVel) {
        int forward = (held.contains(Key.FORWARD) ? 1 : 0) - (held.contains(Key.BACK) ? 1 : 0);
        int left = (held.contains(Key.LEFT) ? 1 : 0) - (held.contains(Key.RIGHT) ? 1 : 0);
        return new Drive(forward * vel, left * rotVel);
    }
}
