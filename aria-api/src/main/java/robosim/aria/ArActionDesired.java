package robosim.aria;

import java.util.ArrayList;
import java.util.List;

/**
 * What an action wants this cycle, as ARIA's {@code ArActionDesired} (ArActionDesired.h): a
 * translational velocity, a rotational velocity or a heading (absolute or delta), and maximum
 * velocities and accelerations, each channel with its own strength in [0, 1].
 *
 * <p>The resolver combines the desires of all active actions (see {@link ArPriorityResolver}). The
 * maximum and acceleration channels combine by the safer value by default (the slowest maximum or
 * acceleration, the fastest deceleration); pass {@code useSlowest = false} to have them averaged by
 * strength like the velocity channels. An absolute heading becomes a delta heading against the
 * robot's heading when the resolver calls {@link #accountForRobotHeading}. The lateral channels of
 * ARIA's class are absent: no RoboSim robot moves sideways.
 */
public class ArActionDesired {
    /** No strength. */
    public static final double NO_STRENGTH = ArActionDesiredChannel.NO_STRENGTH;
    /** The least strength that counts. */
    public static final double MIN_STRENGTH = ArActionDesiredChannel.MIN_STRENGTH;
    /** The greatest strength. */
    public static final double MAX_STRENGTH = ArActionDesiredChannel.MAX_STRENGTH;

    private final ArActionDesiredChannel vel = new ArActionDesiredChannel();
    private final ArActionDesiredChannel maxVel = new ArActionDesiredChannel();
    private final ArActionDesiredChannel maxNegVel = new ArActionDesiredChannel();
    private final ArActionDesiredChannel transAccel = new ArActionDesiredChannel();
    private final ArActionDesiredChannel transDecel = new ArActionDesiredChannel();
    private final ArActionDesiredChannel rotVel = new ArActionDesiredChannel();
    private final ArActionDesiredChannel deltaHeading = new ArActionDesiredChannel();
    private final ArActionDesiredChannel maxRotVel = new ArActionDesiredChannel();
    private final ArActionDesiredChannel maxRotVelPos = new ArActionDesiredChannel();
    private final ArActionDesiredChannel maxRotVelNeg = new ArActionDesiredChannel();
    private final ArActionDesiredChannel rotAccel = new ArActionDesiredChannel();
    private final ArActionDesiredChannel rotDecel = new ArActionDesiredChannel();
    private final ArActionDesiredChannel latVel = new ArActionDesiredChannel();
    private final ArActionDesiredChannel maxLeftLatVel = new ArActionDesiredChannel();
    private final ArActionDesiredChannel maxRightLatVel = new ArActionDesiredChannel();
    private final ArActionDesiredChannel latAccel = new ArActionDesiredChannel();
    private final ArActionDesiredChannel latDecel = new ArActionDesiredChannel();
    private final List<ArActionDesiredChannel> all = new ArrayList<>();
    private double heading;
    private double headingStrength = MIN_STRENGTH;
    private boolean headingSet;

    /** Nothing desired. */
    public ArActionDesired() {
        all.add(vel);
        all.add(maxVel);
        all.add(maxNegVel);
        all.add(transAccel);
        all.add(transDecel);
        all.add(rotVel);
        all.add(deltaHeading);
        all.add(maxRotVel);
        all.add(maxRotVelPos);
        all.add(maxRotVelNeg);
        all.add(rotAccel);
        all.add(rotDecel);
        all.add(latVel);
        all.add(maxLeftLatVel);
        all.add(maxRightLatVel);
        all.add(latAccel);
        all.add(latDecel);
        transDecel.setOverrideDoesLessThan(false);
        rotDecel.setOverrideDoesLessThan(false);
        maxNegVel.setOverrideDoesLessThan(false);
    }

    /** @param value the desired translational velocity, mm/s, at full strength */
    public void setVel(double value) {
        setVel(value, MAX_STRENGTH);
    }

    /**
     * @param value    the desired translational velocity, mm/s
     * @param strength how strongly, 0 to 1
     */
    public void setVel(double value, double strength) {
        vel.setDesired(value, strength, false);
    }

    /** @return the desired translational velocity, mm/s */
    public double getVel() {
        return vel.getDesired();
    }

    /** @return the strength of the translational velocity, mm/s, 0 when not desired */
    public double getVelStrength() {
        return vel.getStrength();
    }

    /** @param value the desired maximum forward velocity, mm/s, at full strength; the slowest value wins */
    public void setMaxVel(double value) {
        setMaxVel(value, MAX_STRENGTH, true);
    }

    /**
     * @param value    the desired maximum forward velocity, mm/s; the slowest value wins
     * @param strength how strongly, 0 to 1
     */
    public void setMaxVel(double value, double strength) {
        setMaxVel(value, strength, true);
    }

    /**
     * @param value    the desired maximum forward velocity, mm/s
     * @param strength how strongly, 0 to 1
     * @param useSlowest whether the slowest value wins (true) or the values are averaged by strength (false)
     */
    public void setMaxVel(double value, double strength, boolean useSlowest) {
        maxVel.setDesired(value, strength, useSlowest);
    }

    /** @return the desired maximum forward velocity, mm/s */
    public double getMaxVel() {
        return maxVel.getDesired();
    }

    /** @return the strength of the maximum forward velocity, mm/s, 0 when not desired */
    public double getMaxVelStrength() {
        return maxVel.getStrength();
    }

    /** @return whether the slowest value wins in this channel */
    public boolean getMaxVelSlowestUsed() {
        return maxVel.getAllowOverride();
    }

    /** @param value the desired maximum backward velocity, mm/s (negative), at full strength; the slowest value wins */
    public void setMaxNegVel(double value) {
        setMaxNegVel(value, MAX_STRENGTH, true);
    }

    /**
     * @param value    the desired maximum backward velocity, mm/s (negative); the slowest value wins
     * @param strength how strongly, 0 to 1
     */
    public void setMaxNegVel(double value, double strength) {
        setMaxNegVel(value, strength, true);
    }

    /**
     * @param value    the desired maximum backward velocity, mm/s (negative)
     * @param strength how strongly, 0 to 1
     * @param useSlowest whether the slowest value wins (true) or the values are averaged by strength (false)
     */
    public void setMaxNegVel(double value, double strength, boolean useSlowest) {
        maxNegVel.setDesired(value, strength, useSlowest);
    }

    /** @return the desired maximum backward velocity, mm/s (negative) */
    public double getMaxNegVel() {
        return maxNegVel.getDesired();
    }

    /** @return the strength of the maximum backward velocity, mm/s (negative), 0 when not desired */
    public double getMaxNegVelStrength() {
        return maxNegVel.getStrength();
    }

    /** @return whether the slowest value wins in this channel */
    public boolean getMaxNegVelSlowestUsed() {
        return maxNegVel.getAllowOverride();
    }

    /** @param value the desired translational acceleration, mm/s², at full strength; the slowest value wins */
    public void setTransAccel(double value) {
        setTransAccel(value, MAX_STRENGTH, true);
    }

    /**
     * @param value    the desired translational acceleration, mm/s²; the slowest value wins
     * @param strength how strongly, 0 to 1
     */
    public void setTransAccel(double value, double strength) {
        setTransAccel(value, strength, true);
    }

    /**
     * @param value    the desired translational acceleration, mm/s²
     * @param strength how strongly, 0 to 1
     * @param useSlowest whether the slowest value wins (true) or the values are averaged by strength (false)
     */
    public void setTransAccel(double value, double strength, boolean useSlowest) {
        transAccel.setDesired(value, strength, useSlowest);
    }

    /** @return the desired translational acceleration, mm/s² */
    public double getTransAccel() {
        return transAccel.getDesired();
    }

    /** @return the strength of the translational acceleration, mm/s², 0 when not desired */
    public double getTransAccelStrength() {
        return transAccel.getStrength();
    }

    /** @return whether the slowest value wins in this channel */
    public boolean getTransAccelSlowestUsed() {
        return transAccel.getAllowOverride();
    }

    /** @param value the desired translational deceleration, mm/s², at full strength; the fastest deceleration wins */
    public void setTransDecel(double value) {
        setTransDecel(value, MAX_STRENGTH, true);
    }

    /**
     * @param value    the desired translational deceleration, mm/s²; the fastest deceleration wins
     * @param strength how strongly, 0 to 1
     */
    public void setTransDecel(double value, double strength) {
        setTransDecel(value, strength, true);
    }

    /**
     * @param value    the desired translational deceleration, mm/s²
     * @param strength how strongly, 0 to 1
     * @param useFastest whether the fastest deceleration wins (true) or the values are averaged by strength (false)
     */
    public void setTransDecel(double value, double strength, boolean useFastest) {
        transDecel.setDesired(value, strength, useFastest);
    }

    /** @return the desired translational deceleration, mm/s² */
    public double getTransDecel() {
        return transDecel.getDesired();
    }

    /** @return the strength of the translational deceleration, mm/s², 0 when not desired */
    public double getTransDecelStrength() {
        return transDecel.getStrength();
    }

    /** @return whether the fastest value wins in this channel */
    public boolean getTransDecelFastestUsed() {
        return transDecel.getAllowOverride();
    }

    /** @param value the desired rotational velocity, deg/s, at full strength */
    public void setRotVel(double value) {
        setRotVel(value, MAX_STRENGTH);
    }

    /**
     * @param value    the desired rotational velocity, deg/s
     * @param strength how strongly, 0 to 1
     */
    public void setRotVel(double value, double strength) {
        rotVel.setDesired(value, strength, false);
    }

    /** @return the desired rotational velocity, deg/s */
    public double getRotVel() {
        return rotVel.getDesired();
    }

    /** @return the strength of the rotational velocity, deg/s, 0 when not desired */
    public double getRotVelStrength() {
        return rotVel.getStrength();
    }

    /** @param value the desired change of heading, degrees, at full strength */
    public void setDeltaHeading(double value) {
        setDeltaHeading(value, MAX_STRENGTH);
    }

    /**
     * @param value    the desired change of heading, degrees
     * @param strength how strongly, 0 to 1
     */
    public void setDeltaHeading(double value, double strength) {
        deltaHeading.setDesired(value, strength, false);
    }

    /** @return the desired change of heading, degrees */
    public double getDeltaHeading() {
        return deltaHeading.getDesired();
    }

    /** @return the strength of the change of heading, degrees, 0 when not desired */
    public double getDeltaHeadingStrength() {
        return deltaHeading.getStrength();
    }

    /** @param value the desired maximum rotational velocity, deg/s, at full strength; the slowest value wins */
    public void setMaxRotVel(double value) {
        setMaxRotVel(value, MAX_STRENGTH, true);
    }

    /**
     * @param value    the desired maximum rotational velocity, deg/s; the slowest value wins
     * @param strength how strongly, 0 to 1
     */
    public void setMaxRotVel(double value, double strength) {
        setMaxRotVel(value, strength, true);
    }

    /**
     * @param value    the desired maximum rotational velocity, deg/s
     * @param strength how strongly, 0 to 1
     * @param useSlowest whether the slowest value wins (true) or the values are averaged by strength (false)
     */
    public void setMaxRotVel(double value, double strength, boolean useSlowest) {
        maxRotVel.setDesired(value, strength, useSlowest);
    }

    /** @return the desired maximum rotational velocity, deg/s */
    public double getMaxRotVel() {
        return maxRotVel.getDesired();
    }

    /** @return the strength of the maximum rotational velocity, deg/s, 0 when not desired */
    public double getMaxRotVelStrength() {
        return maxRotVel.getStrength();
    }

    /** @return whether the slowest value wins in this channel */
    public boolean getMaxRotVelSlowestUsed() {
        return maxRotVel.getAllowOverride();
    }

    /** @param value the desired maximum counter-clockwise rotational velocity, deg/s, at full strength; the slowest value wins */
    public void setMaxRotVelPos(double value) {
        setMaxRotVelPos(value, MAX_STRENGTH, true);
    }

    /**
     * @param value    the desired maximum counter-clockwise rotational velocity, deg/s; the slowest value wins
     * @param strength how strongly, 0 to 1
     */
    public void setMaxRotVelPos(double value, double strength) {
        setMaxRotVelPos(value, strength, true);
    }

    /**
     * @param value    the desired maximum counter-clockwise rotational velocity, deg/s
     * @param strength how strongly, 0 to 1
     * @param useSlowest whether the slowest value wins (true) or the values are averaged by strength (false)
     */
    public void setMaxRotVelPos(double value, double strength, boolean useSlowest) {
        maxRotVelPos.setDesired(value, strength, useSlowest);
    }

    /** @return the desired maximum counter-clockwise rotational velocity, deg/s */
    public double getMaxRotVelPos() {
        return maxRotVelPos.getDesired();
    }

    /** @return the strength of the maximum counter-clockwise rotational velocity, deg/s, 0 when not desired */
    public double getMaxRotVelPosStrength() {
        return maxRotVelPos.getStrength();
    }

    /** @return whether the slowest value wins in this channel */
    public boolean getMaxRotVelPosSlowestUsed() {
        return maxRotVelPos.getAllowOverride();
    }

    /** @param value the desired maximum clockwise rotational velocity, deg/s (a magnitude), at full strength; the slowest value wins */
    public void setMaxRotVelNeg(double value) {
        setMaxRotVelNeg(value, MAX_STRENGTH, true);
    }

    /**
     * @param value    the desired maximum clockwise rotational velocity, deg/s (a magnitude); the slowest value wins
     * @param strength how strongly, 0 to 1
     */
    public void setMaxRotVelNeg(double value, double strength) {
        setMaxRotVelNeg(value, strength, true);
    }

    /**
     * @param value    the desired maximum clockwise rotational velocity, deg/s (a magnitude)
     * @param strength how strongly, 0 to 1
     * @param useSlowest whether the slowest value wins (true) or the values are averaged by strength (false)
     */
    public void setMaxRotVelNeg(double value, double strength, boolean useSlowest) {
        maxRotVelNeg.setDesired(value, strength, useSlowest);
    }

    /** @return the desired maximum clockwise rotational velocity, deg/s (a magnitude) */
    public double getMaxRotVelNeg() {
        return maxRotVelNeg.getDesired();
    }

    /** @return the strength of the maximum clockwise rotational velocity, deg/s (a magnitude), 0 when not desired */
    public double getMaxRotVelNegStrength() {
        return maxRotVelNeg.getStrength();
    }

    /** @return whether the slowest value wins in this channel */
    public boolean getMaxRotVelNegSlowestUsed() {
        return maxRotVelNeg.getAllowOverride();
    }

    /** @param value the desired rotational acceleration, deg/s², at full strength; the slowest value wins */
    public void setRotAccel(double value) {
        setRotAccel(value, MAX_STRENGTH, true);
    }

    /**
     * @param value    the desired rotational acceleration, deg/s²; the slowest value wins
     * @param strength how strongly, 0 to 1
     */
    public void setRotAccel(double value, double strength) {
        setRotAccel(value, strength, true);
    }

    /**
     * @param value    the desired rotational acceleration, deg/s²
     * @param strength how strongly, 0 to 1
     * @param useSlowest whether the slowest value wins (true) or the values are averaged by strength (false)
     */
    public void setRotAccel(double value, double strength, boolean useSlowest) {
        rotAccel.setDesired(value, strength, useSlowest);
    }

    /** @return the desired rotational acceleration, deg/s² */
    public double getRotAccel() {
        return rotAccel.getDesired();
    }

    /** @return the strength of the rotational acceleration, deg/s², 0 when not desired */
    public double getRotAccelStrength() {
        return rotAccel.getStrength();
    }

    /** @return whether the slowest value wins in this channel */
    public boolean getRotAccelSlowestUsed() {
        return rotAccel.getAllowOverride();
    }

    /** @param value the desired rotational deceleration, deg/s², at full strength; the fastest deceleration wins */
    public void setRotDecel(double value) {
        setRotDecel(value, MAX_STRENGTH, true);
    }

    /**
     * @param value    the desired rotational deceleration, deg/s²; the fastest deceleration wins
     * @param strength how strongly, 0 to 1
     */
    public void setRotDecel(double value, double strength) {
        setRotDecel(value, strength, true);
    }

    /**
     * @param value    the desired rotational deceleration, deg/s²
     * @param strength how strongly, 0 to 1
     * @param useFastest whether the fastest deceleration wins (true) or the values are averaged by strength (false)
     */
    public void setRotDecel(double value, double strength, boolean useFastest) {
        rotDecel.setDesired(value, strength, useFastest);
    }

    /** @return the desired rotational deceleration, deg/s² */
    public double getRotDecel() {
        return rotDecel.getDesired();
    }

    /** @return the strength of the rotational deceleration, deg/s², 0 when not desired */
    public double getRotDecelStrength() {
        return rotDecel.getStrength();
    }

    /** @return whether the fastest value wins in this channel */
    public boolean getRotDecelFastestUsed() {
        return rotDecel.getAllowOverride();
    }

    /**
     * An absolute heading; the resolver turns it into a delta heading against the robot's heading.
     * It does nothing when a rotational velocity is desired with more strength earlier.
     *
     * @param value    the heading, degrees
     * @param strength how strongly, 0 to 1
     */
    public void setHeading(double value, double strength) {
        heading = value;
        headingStrength = strength;
        headingSet = true;
    }

    /** @param value the heading, degrees, at full strength */
    public void setHeading(double value) {
        setHeading(value, MAX_STRENGTH);
    }

    /** @return the absolute heading set, degrees */
    public double getHeading() {
        return heading;
    }

    /** @return the absolute heading's strength */
    public double getHeadingStrength() {
        return headingStrength;
    }

    // ---- the lateral channels (ARIA's, for robots that move sideways; no simulated robot does,
    // so the resolver combines them and nothing sends them) ----

    /** @param value the desired lateral velocity, mm/s, left positive, at full strength */
    public void setLeftLatVel(double value) {
        setLeftLatVel(value, MAX_STRENGTH);
    }

    /**
     * @param value    the desired lateral velocity, mm/s, left positive
     * @param strength how strongly, 0 to 1
     */
    public void setLeftLatVel(double value, double strength) {
        latVel.setDesired(value, strength, false);
    }

    /** @param value the desired lateral velocity to the right, mm/s, at full strength */
    public void setRightLatVel(double value) {
        setRightLatVel(value, MAX_STRENGTH);
    }

    /**
     * As ARIA's: the left lateral velocity, negated.
     *
     * @param value    the desired lateral velocity to the right, mm/s
     * @param strength how strongly, 0 to 1
     */
    public void setRightLatVel(double value, double strength) {
        latVel.setDesired(-value, strength, false);
    }

    /** @return the desired lateral velocity, mm/s, left positive */
    public double getLatVel() {
        return latVel.getDesired();
    }

    /** @return its strength */
    public double getLatVelStrength() {
        return latVel.getStrength();
    }

    /** @param value the desired maximum lateral velocity to the left, mm/s; the slowest wins */
    public void setMaxLeftLatVel(double value) {
        setMaxLeftLatVel(value, MAX_STRENGTH, true);
    }

    /**
     * @param value    the desired maximum lateral velocity to the left, mm/s
     * @param strength how strongly, 0 to 1
     */
    public void setMaxLeftLatVel(double value, double strength) {
        setMaxLeftLatVel(value, strength, true);
    }

    /**
     * @param value      the desired maximum lateral velocity to the left, mm/s
     * @param strength   how strongly, 0 to 1
     * @param useSlowest whether the slowest value wins
     */
    public void setMaxLeftLatVel(double value, double strength, boolean useSlowest) {
        maxLeftLatVel.setDesired(value, strength, useSlowest);
    }

    /** @return the desired maximum lateral velocity to the left, mm/s */
    public double getMaxLeftLatVel() {
        return maxLeftLatVel.getDesired();
    }

    /** @return its strength */
    public double getMaxLeftLatVelStrength() {
        return maxLeftLatVel.getStrength();
    }

    /** @return whether the slowest value wins in this channel */
    public boolean getMaxLeftLatVelSlowestUsed() {
        return maxLeftLatVel.getAllowOverride();
    }

    /** @param value the desired maximum lateral velocity to the right, mm/s; the slowest wins */
    public void setMaxRightLatVel(double value) {
        setMaxRightLatVel(value, MAX_STRENGTH, true);
    }

    /**
     * @param value    the desired maximum lateral velocity to the right, mm/s
     * @param strength how strongly, 0 to 1
     */
    public void setMaxRightLatVel(double value, double strength) {
        setMaxRightLatVel(value, strength, true);
    }

    /**
     * @param value      the desired maximum lateral velocity to the right, mm/s
     * @param strength   how strongly, 0 to 1
     * @param useSlowest whether the slowest value wins
     */
    public void setMaxRightLatVel(double value, double strength, boolean useSlowest) {
        maxRightLatVel.setDesired(value, strength, useSlowest);
    }

    /** @return the desired maximum lateral velocity to the right, mm/s */
    public double getMaxRightLatVel() {
        return maxRightLatVel.getDesired();
    }

    /** @return its strength */
    public double getMaxRightLatVelStrength() {
        return maxRightLatVel.getStrength();
    }

    /** @return whether the slowest value wins in this channel */
    public boolean getMaxRightLatVelSlowestUsed() {
        return maxRightLatVel.getAllowOverride();
    }

    /** @param value the desired lateral acceleration, mm/s²; the slowest wins */
    public void setLatAccel(double value) {
        setLatAccel(value, MAX_STRENGTH, true);
    }

    /**
     * @param value    the desired lateral acceleration, mm/s²
     * @param strength how strongly, 0 to 1
     */
    public void setLatAccel(double value, double strength) {
        setLatAccel(value, strength, true);
    }

    /**
     * @param value      the desired lateral acceleration, mm/s²
     * @param strength   how strongly, 0 to 1
     * @param useSlowest whether the slowest value wins
     */
    public void setLatAccel(double value, double strength, boolean useSlowest) {
        latAccel.setDesired(value, strength, useSlowest);
    }

    /** @return the desired lateral acceleration, mm/s² */
    public double getLatAccel() {
        return latAccel.getDesired();
    }

    /** @return its strength */
    public double getLatAccelStrength() {
        return latAccel.getStrength();
    }

    /** @return whether the slowest value wins in this channel */
    public boolean getLatAccelSlowestUsed() {
        return latAccel.getAllowOverride();
    }

    /** @param value the desired lateral deceleration, mm/s² */
    public void setLatDecel(double value) {
        setLatDecel(value, MAX_STRENGTH, true);
    }

    /**
     * @param value    the desired lateral deceleration, mm/s²
     * @param strength how strongly, 0 to 1
     */
    public void setLatDecel(double value, double strength) {
        setLatDecel(value, strength, true);
    }

    /**
     * As ARIA's, this channel keeps the channels' default rule (ARIA's does not set the
     * fastest-deceleration rule on it, as it does for the translational and rotational ones).
     *
     * @param value      the desired lateral deceleration, mm/s²
     * @param strength   how strongly, 0 to 1
     * @param useFastest ARIA's flag for the channel's override
     */
    public void setLatDecel(double value, double strength, boolean useFastest) {
        latDecel.setDesired(value, strength, useFastest);
    }

    /** @return the desired lateral deceleration, mm/s² */
    public double getLatDecel() {
        return latDecel.getDesired();
    }

    /** @return its strength */
    public double getLatDecelStrength() {
        return latDecel.getStrength();
    }

    /** @return whether the fastest value wins in this channel */
    public boolean getLatDecelFastestUsed() {
        return latDecel.getAllowOverride();
    }

    /** Nothing desired again. */
    public void reset() {
        for (ArActionDesiredChannel c : all) {
            c.reset();
        }
        headingStrength = 0;
        headingSet = false;
    }

    /**
     * Turns a set absolute heading into a delta heading from the robot's heading, as ARIA's
     * resolvers do before merging.
     *
     * @param robotHeading the robot's heading now, degrees
     */
    public void accountForRobotHeading(double robotHeading) {
        if (headingSet) {
            setDeltaHeading(ArMath.subAngle(heading, robotHeading), headingStrength);
        }
        headingSet = false;
    }

    /**
     * Merges a lower-priority desire into this one, channel by channel (see
     * {@link ArActionDesiredChannel#merge}); a rotational velocity and a delta heading do not mix:
     * whichever this desire already has takes the other's channel of the same kind only.
     *
     * @param other the lower-priority desire; null changes nothing
     */
    public void merge(ArActionDesired other) {
        if (other == null) {
            return;
        }
        for (int i = 0; i < all.size(); i++) {
            ArActionDesiredChannel c = all.get(i);
            if (c == rotVel || c == deltaHeading) {
                continue;
            }
            c.merge(other.all.get(i));
        }
        if (deltaHeading.getStrength() > NO_STRENGTH) {
            deltaHeading.merge(other.deltaHeading);
        } else if (rotVel.getStrength() > NO_STRENGTH) {
            rotVel.merge(other.rotVel);
        } else {
            deltaHeading.merge(other.deltaHeading);
            rotVel.merge(other.rotVel);
        }
    }

    /** Starts averaging the desires of one priority. */
    public void startAverage() {
        for (ArActionDesiredChannel c : all) {
            c.startAverage();
        }
    }

    /** @param other a desire of the same priority, added to the average; null changes nothing */
    public void addAverage(ArActionDesired other) {
        if (other == null) {
            return;
        }
        for (int i = 0; i < all.size(); i++) {
            ArActionDesiredChannel c = all.get(i);
            if (c == rotVel || c == deltaHeading) {
                continue;
            }
            c.addAverage(other.all.get(i));
        }
        if (rotVel.getStrength() > NO_STRENGTH) {
            rotVel.addAverage(other.rotVel);
        } else if (deltaHeading.getStrength() > NO_STRENGTH) {
            deltaHeading.addAverage(other.deltaHeading);
        } else {
            rotVel.addAverage(other.rotVel);
            deltaHeading.addAverage(other.deltaHeading);
        }
    }

    /** Ends the average of one priority. */
    public void endAverage() {
        for (ArActionDesiredChannel c : all) {
            c.endAverage();
        }
    }

    /** @return whether any channel (or the absolute heading) has strength */
    public boolean isAnythingDesired() {
        if (headingStrength >= MIN_STRENGTH && headingSet) {
            return true;
        }
        for (ArActionDesiredChannel c : all) {
            if (c.getStrength() >= MIN_STRENGTH) {
                return true;
            }
        }
        return false;
    }

    /**
     * Clamps values no robot can use, with a log line naming the action, as ARIA's
     * {@code ArActionDesired::sanityCheck} does: maximum velocities and accelerations below their
     * floors, a maximum backward velocity above 0.
     *
     * @param actionName the action the desire came from
     */
    public void sanityCheck(String actionName) {
        maxVel.checkLowerBound(actionName, "TransMaxVel", 0);
        maxNegVel.checkUpperBound(actionName, "TransMaxNegVel", 0);
        transAccel.checkLowerBound(actionName, "TransAccel", 1);
        transDecel.checkLowerBound(actionName, "TransDecel", 1);
        maxRotVel.checkLowerBound(actionName, "MaxRotVel", 0);
        maxRotVelPos.checkLowerBound(actionName, "MaxRotVelPos", 1);
        maxRotVelNeg.checkLowerBound(actionName, "MaxRotVelNeg", 1);
        rotAccel.checkLowerBound(actionName, "RotAccel", 1);
        rotDecel.checkLowerBound(actionName, "RotDecel", 1);
        maxLeftLatVel.checkLowerBound(actionName, "MaxLeftLatVel", 0);
        maxRightLatVel.checkLowerBound(actionName, "MaxRightLatVel", 0);
        latAccel.checkLowerBound(actionName, "LatAccel", 1);
        latDecel.checkLowerBound(actionName, "LatDecel", 1);
    }

    /** @return a copy, as ARIA passes the current desire to {@code fire} by value */
    public ArActionDesired copy() {
        ArActionDesired d = new ArActionDesired();
        for (int i = 0; i < all.size(); i++) {
            d.all.get(i).copyFrom(all.get(i));
        }
        d.heading = heading;
        d.headingStrength = headingStrength;
        d.headingSet = headingSet;
        return d;
    }

    /** @return the channels with strength, as ARIA's {@code log} prints them */
    @Override
    public String toString() {
        StringBuilder b = new StringBuilder("ArActionDesired[");
        append(b, "Vel", vel);
        append(b, "MaxVel", maxVel);
        append(b, "MaxNegVel", maxNegVel);
        append(b, "TransAccel", transAccel);
        append(b, "TransDecel", transDecel);
        append(b, "RotVel", rotVel);
        append(b, "DeltaHeading", deltaHeading);
        append(b, "MaxRotVel", maxRotVel);
        append(b, "MaxRotVelPos", maxRotVelPos);
        append(b, "MaxRotVelNeg", maxRotVelNeg);
        append(b, "RotAccel", rotAccel);
        append(b, "RotDecel", rotDecel);
        append(b, "LatVel", latVel);
        append(b, "MaxLeftLatVel", maxLeftLatVel);
        append(b, "MaxRightLatVel", maxRightLatVel);
        append(b, "LatAccel", latAccel);
        append(b, "LatDecel", latDecel);
        if (headingSet && headingStrength >= MIN_STRENGTH) {
            b.append(String.format(" Heading %.0f (%.2f)", heading, headingStrength));
        }
        return b.append(" ]").toString();
    }

    private static void append(StringBuilder b, String name, ArActionDesiredChannel c) {
        if (c.getStrength() >= MIN_STRENGTH) {
            b.append(String.format(" %s %.0f (%.2f)", name, c.getDesired(), c.getStrength()));
        }
    }
}
