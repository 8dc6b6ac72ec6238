package robosim.aria;

/**
 * A moment in simulated time (ARIA's {@code ArTime}, ariaUtil.h), to the millisecond. "Now" is the
 * simulated time of the robot the calling thread belongs to, else of the latest state a robot of the
 * default {@link robosim.hw.RobotRuntime} received (see docs/ARIA-SEMANTICS.md); robots run in lockstep, so all of them see the same
 * time, and a program's timing repeats exactly from run to run. Simulated time starts at 0 (ARIA's
 * clock starts a million seconds on, to leave room to go back; here going below 0 is refused).
 *
 * <p>ARIA's argument order is kept: {@code t.mSecSince(other)} is {@code other − t}, so
 * {@code t.mSecSince(now)} is the time since {@code t}; {@code t.isBefore(other)} is true when
 * {@code other} is earlier than {@code t}, and {@code t.isAfter(other)} when it is later.
 *
 * <pre>{@code
 * ArTime start = new ArTime();
 * robot.setVel(200);
 * while (start.mSecSince() < 2000) ArUtil.sleep(100);
 * }</pre>
 */
public final class ArTime {
    private long ms;

    /** A time set to now. */
    public ArTime() {
        setToNow();
    }

    /**
     * @param ms simulated ms since the start of the run
     * @return a time set to them, for readings stamped in ms
     */
    static ArTime ofMs(long ms) {
        ArTime t = new ArTime(0L);
        t.ms = ms;
        return t;
    }

    /** A time not set from the clock, for {@link #ofMs}. */
    private ArTime(long ignored) {
    }

    /** @param other a time to copy */
    public ArTime(ArTime other) {
        this.ms = other.ms;
    }

    /** Sets this time to now, in simulated time. */
    public void setToNow() {
        ms = SimulatedClock.nowMs();
    }

    /**
     * @param since another time
     * @return {@code since − this}, ms (ARIA's order)
     */
    public long mSecSince(ArTime since) {
        return since.ms - ms;
    }

    /** @param since another time @return as {@link #mSecSince(ArTime)} (ARIA's 64-bit name) */
    public long mSecSinceLL(ArTime since) {
        return mSecSince(since);
    }

    /** @param since another time @return {@code since − this}, whole seconds, truncated */
    public long secSince(ArTime since) {
        return mSecSince(since) / 1000;
    }

    /** @param since another time @return as {@link #secSince(ArTime)} */
    public long secSinceLL(ArTime since) {
        return secSince(since);
    }

    /** @return the ms from this time to now */
    public long mSecSince() {
        return mSecSince(new ArTime());
    }

    /** @return as {@link #mSecSince()} */
    public long mSecSinceLL() {
        return mSecSince();
    }

    /** @return the whole seconds from this time to now, truncated */
    public long secSince() {
        return mSecSince() / 1000;
    }

    /** @return as {@link #secSince()} */
    public long secSinceLL() {
        return secSince();
    }

    /** @return the seconds from this time to now */
    public double secSinceDouble() {
        return mSecSince() / 1000.0;
    }

    /** @return the ms from now to this time (negative when it is past) */
    public long mSecTo() {
        return -mSecSince();
    }

    /** @return as {@link #mSecTo()} */
    public long mSecToLL() {
        return mSecTo();
    }

    /** @return the whole seconds from now to this time, truncated */
    public long secTo() {
        return mSecTo() / 1000;
    }

    /** @return as {@link #secTo()} */
    public long secToLL() {
        return secTo();
    }

    /** @param testTime another time @return whether {@code testTime} is earlier than this one (ARIA's order) */
    public boolean isBefore(ArTime testTime) {
        return mSecSince(testTime) < 0;
    }

    /** @param testTime another time @return whether it is the same moment */
    public boolean isAt(ArTime testTime) {
        return mSecSince(testTime) == 0;
    }

    /** @param testTime another time @return whether {@code testTime} is later than this one (ARIA's order) */
    public boolean isAfter(ArTime testTime) {
        return mSecSince(testTime) > 0;
    }

    /**
     * Moves this time by some milliseconds.
     *
     * @param msToAdd ms, negative to go back
     * @return true; false if the time would go below 0, which sets it to 0 (as ARIA's does)
     */
    public boolean addMSec(long msToAdd) {
        if (msToAdd < 0 && -msToAdd > ms) {
            ms = 0;
            return false;
        }
        ms += msToAdd;
        return true;
    }

    /** @param msToAdd ms @return as {@link #addMSec(long)} */
    public boolean addMSecLL(long msToAdd) {
        return addMSec(msToAdd);
    }

    /** @return the whole seconds of this time */
    public long getSec() {
        return ms / 1000;
    }

    /** @return the milliseconds past the whole second, 0 to 999 */
    public long getMSec() {
        return ms % 1000;
    }

    /** @return as {@link #getSec()} */
    public long getSecLL() {
        return getSec();
    }

    /** @return as {@link #getMSec()} */
    public long getMSecLL() {
        return getMSec();
    }

    /**
     * @param sec the whole seconds, 0 or more; the milliseconds past the second are kept
     * @throws IllegalArgumentException if negative
     */
    public void setSec(long sec) {
        if (sec < 0) {
            throw new IllegalArgumentException(sec + " was supplied for sec: simulated time is 0 or more");
        }
        ms = sec * 1000 + getMSec();
    }

    /**
     * @param msec the milliseconds past the whole second; 1000 or more carry into the seconds, as
     *             ARIA's do when it adds them up
     * @throws IllegalArgumentException if negative
     */
    public void setMSec(long msec) {
        if (msec < 0) {
            throw new IllegalArgumentException(msec + " was supplied for msec: simulated time is 0 or more");
        }
        ms = getSec() * 1000 + msec;
    }

    /** @return the time as simulated ms since the start of the run */
    public long getTimeMs() {
        return ms;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof ArTime t && t.ms == ms;
    }

    @Override
    public int hashCode() {
        return Long.hashCode(ms);
    }

    @Override
    public String toString() {
        return "ArTime(" + getSec() + " s " + getMSec() + " ms)";
    }
}
