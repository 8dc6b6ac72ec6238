package robosim.aria;

/**
 * One channel of an {@link ArActionDesired}: a desired value with a strength in [0, 1], and ARIA's
 * rules for merging channels across priorities and averaging them within one priority (as ARIA's
 * {@code ArActionDesired.h} defines {@code ArActionDesiredChannel}).
 *
 * <p>A channel set with "override" (the maximum and acceleration channels, by default) combines by
 * taking the least value, or the greatest for the channels where that is the safer one (the
 * decelerations and the maximum backwards velocity); any other channel combines as the
 * strength-weighted average. Strength below {@link #MIN_STRENGTH} counts as none; strengths add up
 * to at most {@link #MAX_STRENGTH}.
 */
public final class ArActionDesiredChannel {
    /** No strength: the channel is not desired. */
    public static final double NO_STRENGTH = 0.0;
    /** The least strength that counts. */
    public static final double MIN_STRENGTH = 0.000001;
    /** The greatest strength; merged strengths are capped here. */
    public static final double MAX_STRENGTH = 1.0;

    private double desired;
    private double strength = NO_STRENGTH;
    private boolean allowOverride = true;
    private double desiredTotal;
    private double strengthTotal;
    private boolean overrideDoesLessThan = true;

    /** A channel with nothing desired. */
    public ArActionDesiredChannel() {
        reset();
    }

    /** @param lessThan whether an override keeps the least value (true) or the greatest (false) */
    public void setOverrideDoesLessThan(boolean lessThan) {
        overrideDoesLessThan = lessThan;
    }

    /**
     * @param value         the desired value
     * @param valueStrength its strength; capped at {@link #MAX_STRENGTH}, below {@link #MIN_STRENGTH} means none
     * @param override      whether it combines by least/greatest value instead of averaging
     */
    public void setDesired(double value, double valueStrength, boolean override) {
        desired = value;
        strength = Math.min(valueStrength, MAX_STRENGTH);
        allowOverride = override;
        if (strength < MIN_STRENGTH) {
            strength = NO_STRENGTH;
        }
    }

    /** @return the desired value */
    public double getDesired() {
        return desired;
    }

    /** @return the strength, 0 when nothing is desired */
    public double getStrength() {
        return strength;
    }

    /** @return whether the channel combines by least/greatest value */
    public boolean getAllowOverride() {
        return allowOverride;
    }

    /** Nothing desired. */
    public void reset() {
        desired = 0;
        strength = NO_STRENGTH;
        allowOverride = true;
    }

    /**
     * Merges a lower-priority channel into this one: it gets at most the strength left below
     * {@link #MAX_STRENGTH}, and the value is the least/greatest (override) or the average weighted by
     * the strengths.
     *
     * @param other the lower-priority channel
     */
    public void merge(ArActionDesiredChannel other) {
        double otherStrength = other.strength;
        double oldStrength = strength;
        if (strength + otherStrength > MAX_STRENGTH) {
            otherStrength = MAX_STRENGTH - strength;
        }
        strength += otherStrength;
        allowOverride = allowOverride && other.allowOverride;
        if (allowOverride && strength >= MIN_STRENGTH) {
            if (oldStrength >= MIN_STRENGTH && other.strength >= MIN_STRENGTH) {
                desired = pick(desired, other.desired);
            } else if (other.strength >= MIN_STRENGTH) {
                desired = other.desired;
            }
        } else if (strength >= MIN_STRENGTH) {
            desired = (oldStrength * desired + other.desired * otherStrength) / strength;
        }
    }

    /** Starts averaging the channels of one priority, from this channel's own value. */
    public void startAverage() {
        desiredTotal = desired * strength;
        strengthTotal = strength;
    }

    /** @param other a channel of the same priority, added to the average */
    public void addAverage(ArActionDesiredChannel other) {
        allowOverride = allowOverride && other.allowOverride;
        if (allowOverride) {
            if (strength >= MIN_STRENGTH && other.strength >= MIN_STRENGTH) {
                desired = pick(desired, other.desired);
            } else if (other.strength >= MIN_STRENGTH) {
                desired = other.desired;
            }
        }
        desiredTotal += other.desired * other.strength;
        strengthTotal += other.strength;
    }

    /**
     * Ends the average: the value is the strength-weighted mean (or the least/greatest, with
     * override) and the strength the sum, capped at {@link #MAX_STRENGTH}.
     */
    public void endAverage() {
        if (strengthTotal < MIN_STRENGTH) {
            strength = NO_STRENGTH;
            return;
        }
        if (!allowOverride) {
            desired = desiredTotal / strengthTotal;
        }
        strength = Math.min(strengthTotal, MAX_STRENGTH);
    }

    /** Clamps a desired value below a bound, as ARIA's action sanity check does, naming the action. */
    void checkLowerBound(String action, String what, int bound) {
        if (strength >= MIN_STRENGTH && ArMath.roundInt(desired) < bound) {
            ArLogs.sanity(action, what, desired, "less than", bound);
            desired = bound;
        }
    }

    /** Clamps a desired value above a bound. */
    void checkUpperBound(String action, String what, int bound) {
        if (strength >= MIN_STRENGTH && ArMath.roundInt(desired) > bound) {
            ArLogs.sanity(action, what, desired, "greater than", bound);
            desired = bound;
        }
    }

    void copyFrom(ArActionDesiredChannel other) {
        desired = other.desired;
        strength = other.strength;
        allowOverride = other.allowOverride;
        desiredTotal = other.desiredTotal;
        strengthTotal = other.strengthTotal;
        overrideDoesLessThan = other.overrideDoesLessThan;
    }

    private double pick(double a, double b) {
        return overrideDoesLessThan ? Math.min(a, b) : Math.max(a, b);
    }
}
