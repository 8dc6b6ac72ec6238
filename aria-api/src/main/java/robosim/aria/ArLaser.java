package robosim.aria;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

/**
 * ARIA's {@code ArLaser}: what every laser offers a program, whatever its make (ArLaser.h): its
 * number on the robot, its mounting pose, the settings its make allows (a field of view, an angle
 * between readings, units, reflector bits; each either chosen from a list or set within bounds),
 * readings to ignore, whether it is mounted upside down, and the rules of its cumulative buffer.
 * A make says what it allows in its constructor (the {@code laserAllow...} calls); the command line
 * sets them through {@link ArLaserConnector}. RoboSim simulates one make, {@link ArLMS2xx}.
 *
 * <p>Settings are taken when the laser connects; a choice not in the list, or a value out of its
 * bounds, is refused with ARIA's log line and leaves the setting as it was.
 */
public abstract class ArLaser extends ArRangeDevice {
    private final int laserNumber;
    /** The cumulative buffer's rules, as ARIA's lasers apply them. */
    final LaserCumulative cumulativeRules = new LaserCumulative();
    private volatile double connectionTimeoutSeconds;
    private volatile boolean haveSensorPose;
    private volatile ArPose sensorPose = new ArPose();
    private volatile double sensorZ;
    private volatile ArLog.LogLevel infoLogLevel = ArLog.Verbose;
    private final Set<Integer> ignoreReadings = Collections.synchronizedSet(new TreeSet<>());
    private volatile boolean flipped;
    private volatile int defaultTcpPort = 8102;
    private volatile String defaultPortType = "serial";
    private volatile double absoluteMaxRange;
    private final Setting degrees = new Setting("degrees");
    private final Setting increment = new Setting("increment");
    private final Setting units = new Setting("units");
    private final Setting reflectorBits = new Setting("reflectorBits");
    private final Setting startingBaud = new Setting("startingBaud");
    private final Setting autoBaud = new Setting("autoBaud");
    private volatile boolean canSetDegrees;
    private volatile double startDegreesMin;
    private volatile double startDegreesMax;
    private volatile double startDegrees;
    private volatile double endDegreesMin;
    private volatile double endDegreesMax;
    private volatile double endDegrees;
    private volatile boolean canSetIncrement;
    private volatile double incrementMin;
    private volatile double incrementMax;
    private volatile double incrementDegrees;
    private volatile boolean canSetPowerControlled;
    private volatile boolean powerControlled = true;

    /** A setting chosen from a list of names, each perhaps with a number (ARIA's {@code ...Choices}). */
    private static final class Setting {
        final String what;
        final Map<String, Double> choices = new LinkedHashMap<>();
        volatile String choice = "";

        Setting(String what) {
            this.what = what;
        }

        boolean allowed() {
            return !choices.isEmpty();
        }

        String choicesString() {
            return String.join("|", choices.keySet());
        }

        boolean choose(String laser, String name) {
            for (String c : choices.keySet()) {
                if (c.equalsIgnoreCase(name)) {
                    choice = c;
                    return true;
                }
            }
            ArLog.log(ArLog.Normal, "%s: Bad %s choice %s, choices are %s", laser, what, name, choicesString());
            return false;
        }

        double number() {
            Double d = choices.get(choice);
            return d == null ? 0 : d;
        }
    }

    /**
     * @param laserNumber its number on the robot, from 1
     * @param name        its name
     * @param maxRange    the make's absolute maximum range, mm
     */
    protected ArLaser(int laserNumber, String name, double maxRange) {
        this(laserNumber, name, maxRange, 361, 200);
    }

    /**
     * @param laserNumber          its number on the robot, from 1
     * @param name                 its name
     * @param maxRange             the make's absolute maximum range, mm
     * @param currentBufferSize    how many current readings it keeps
     * @param cumulativeBufferSize how many cumulative readings it keeps (0: none)
     */
    protected ArLaser(int laserNumber, String name, double maxRange, int currentBufferSize, int cumulativeBufferSize) {
        super(name, maxRange, currentBufferSize, cumulativeBufferSize);
        this.laserNumber = laserNumber;
        this.absoluteMaxRange = maxRange;
        // ARIA's lasers keep current readings until the next scan replaces them
        setMaxSecondsToKeepCurrent(0);
        setMaxInsertDistCumulative(LaserCumulative.DEFAULT_MAX_INSERT_DIST);
    }

    // ---- connection ----

    /** @return whether the laser connected; waits (bounded) as ARIA's does */
    public abstract boolean blockingConnect();

    /** @return whether connecting began */
    public abstract boolean asyncConnect();

    /** @return whether it was connected and now is not */
    public abstract boolean disconnect();

    /** @return whether it is connected */
    public abstract boolean isConnected();

    /** @return whether it is connecting (a simulated laser connects at once: false) */
    public boolean isTryingToConnect() {
        return false;
    }

    /** @param seconds how long a connection may take; 0 or less for the make's default */
    public void setConnectionTimeoutSeconds(double seconds) {
        connectionTimeoutSeconds = Math.max(0, seconds);
    }

    /** @return how long a connection may take, s; 0 for the make's default */
    public double getConnectionTimeoutSeconds() {
        return connectionTimeoutSeconds;
    }

    /** @return how many readings the latest scan gave */
    public int getReadingCount() {
        return getRawReadings().size();
    }

    /** @return its number on the robot */
    public int getLaserNumber() {
        return laserNumber;
    }

    /** @param level the level the laser logs what it does at */
    public void setInfoLogLevel(ArLog.LogLevel level) {
        infoLogLevel = level;
    }

    /** @return the level the laser logs what it does at */
    public ArLog.LogLevel getInfoLogLevel() {
        return infoLogLevel;
    }

    // ---- mounting ----

    /**
     * @param x  mm forward of the robot's centre
     * @param y  mm to its left
     * @param th degrees from its heading
     */
    public void setSensorPosition(double x, double y, double th) {
        setSensorPosition(new ArPose(x, y, th), 0);
    }

    /** @param x mm forward @param y mm left @param th degrees @param z mm above the floor */
    public void setSensorPosition(double x, double y, double th, double z) {
        setSensorPosition(new ArPose(x, y, th), z);
    }

    /** @param pose the mounting pose @param z mm above the floor */
    public void setSensorPosition(ArPose pose, double z) {
        sensorPose = new ArPose(pose.getX(), pose.getY(), pose.getTh());
        sensorZ = z;
        haveSensorPose = true;
    }

    /** @return whether a mounting pose was given (else the robot's parameter file's is used) */
    public boolean hasSensorPosition() {
        return haveSensorPose;
    }

    /** @return the mounting pose */
    public ArPose getSensorPosition() {
        return sensorPose;
    }

    /** @return mm forward of the robot's centre */
    public double getSensorPositionX() {
        return sensorPose.getX();
    }

    /** @return mm to the robot's left */
    public double getSensorPositionY() {
        return sensorPose.getY();
    }

    /** @return mm above the floor */
    public double getSensorPositionZ() {
        return sensorZ;
    }

    /** @return degrees from the robot's heading */
    public double getSensorPositionTh() {
        return sensorPose.getTh();
    }

    /** @return whether the laser is mounted upside down: its readings' angles are mirrored */
    public boolean getFlipped() {
        return flipped;
    }

    /** @param upsideDown whether it is mounted upside down @return true */
    public boolean setFlipped(boolean upsideDown) {
        flipped = upsideDown;
        return true;
    }

    // ---- readings to ignore, cumulative rules ----

    /**
     * Ignores the readings at some angles (a mount's posts, say), as ARIA's: a list of angles, or
     * ranges {@code a:b} (every whole degree between), separated by commas or spaces.
     *
     * @param list the angles, degrees from the laser's heading
     * @return false if an entry is not a number (logged), the entries before it kept
     */
    public boolean addIgnoreReadings(String list) {
        for (String entry : list.trim().split("[,\\s]+")) {
            if (entry.isEmpty()) {
                continue;
            }
            try {
                String[] ends = entry.split(":");
                if (ends.length == 2) {
                    long a = Math.round(Double.parseDouble(ends[0]));
                    long b = Math.round(Double.parseDouble(ends[1]));
                    for (long d = Math.min(a, b); d <= Math.max(a, b); d++) {
                        ignoreReadings.add((int) d);
                    }
                } else {
                    addIgnoreReading(Double.parseDouble(entry));
                }
            } catch (NumberFormatException e) {
                ArLog.log(ArLog.Terse, "%s: Bad ignore reading '%s' in '%s'", getName(), entry, list);
                return false;
            }
        }
        return true;
    }

    /** @param degrees an angle whose reading is ignored, rounded to the whole degree */
    public void addIgnoreReading(double degrees) {
        ignoreReadings.add((int) Math.round(degrees));
    }

    /** Ignores no reading. */
    public void clearIgnoreReadings() {
        ignoreReadings.clear();
    }

    /** @return the whole-degree angles whose readings are ignored, ascending; a copy */
    public Set<Integer> getIgnoreReadings() {
        synchronized (ignoreReadings) {
            return new TreeSet<>(ignoreReadings);
        }
    }

    /** @return whether a beam at this angle (degrees from the laser's heading) is ignored */
    boolean ignores(double degrees) {
        return !ignoreReadings.isEmpty() && ignoreReadings.contains((int) Math.round(degrees));
    }

    /** @return how close to a beam a cumulative reading is cleared, mm; below 1: never */
    public synchronized double getCumulativeCleanDist() {
        return cumulativeRules.cleanDist;
    }

    /** @param mm how close to a beam a cumulative reading is cleared; below 1: never */
    public synchronized void setCumulativeCleanDist(double mm) {
        cumulativeRules.cleanDist = mm;
    }

    /** @return how often the beams clear the cumulative buffer, simulated ms; 0 or less: every scan */
    public synchronized long getCumulativeCleanInterval() {
        return cumulativeRules.cleanIntervalMs;
    }

    /** @param ms how often the beams clear the cumulative buffer, simulated ms; 0 or less: every scan */
    public synchronized void setCumulativeCleanInterval(long ms) {
        cumulativeRules.cleanIntervalMs = ms;
    }

    /** @param ms added to the time the clean interval restarts from, so that several lasers do not clean at once */
    public synchronized void setCumulativeCleanOffset(long ms) {
        cumulativeRules.cleanOffsetMs = ms;
    }

    /** @return the offset of the first clean, ms */
    public synchronized long getCumulativeCleanOffset() {
        return cumulativeRules.cleanOffsetMs;
    }

    /** Counts the clean interval from the next scan (plus the offset), as ARIA's counts it from now. */
    public synchronized void resetLastCumulativeCleanTime() {
        cumulativeRules.restartCleanInterval();
    }

    // ---- ports (a simulated laser has none) ----

    /** @return the TCP port the make listens on when reached over a network (8102 for an LMS2xx) */
    public int getDefaultTcpPort() {
        return defaultTcpPort;
    }

    /** @return the kind of port the make is usually on ({@code serial} for an LMS2xx) */
    public String getDefaultPortType() {
        return defaultPortType;
    }

    /** @param port the make's TCP port */
    protected void laserSetDefaultTcpPort(int port) {
        defaultTcpPort = port;
    }

    /** @param type the make's kind of port */
    protected void laserSetDefaultPortType(String type) {
        defaultPortType = type;
    }

    // ---- range ----

    /** @return the most the make can measure with its settings, mm */
    public double getAbsoluteMaxRange() {
        return absoluteMaxRange;
    }

    /** @param mm the most the make reports with its settings; the maximum range is capped at it */
    protected void laserSetAbsoluteMaxRange(double mm) {
        absoluteMaxRange = mm;
        if (getMaxRange() > mm) {
            super.setMaxRange(mm);
        }
    }

    /**
     * Sets the maximum range, capped at {@link #getAbsoluteMaxRange()} with ARIA's log line.
     *
     * @param maxRange mm, greater than 0
     */
    @Override
    public void setMaxRange(double maxRange) {
        if (maxRange > absoluteMaxRange) {
            ArLog.log(ArLog.Terse, "%s::setMaxRange: Tried to set max range to %g which is above absoluteMaxRange"
                    + " of %g, capping it", getName(), maxRange, absoluteMaxRange);
            maxRange = absoluteMaxRange;
        }
        super.setMaxRange(maxRange);
    }

    // ---- field of view ----

    /** @return whether the start and end angles may be set within bounds */
    public boolean canSetDegrees() {
        return canSetDegrees;
    }

    /** @return the least start angle, degrees */
    public double getStartDegreesMin() {
        return startDegreesMin;
    }

    /** @return the greatest start angle, degrees */
    public double getStartDegreesMax() {
        return startDegreesMax;
    }

    /** @return the angle of the first reading, degrees from the laser's heading (right is negative) */
    public double getStartDegrees() {
        return startDegrees;
    }

    /**
     * @param value the first reading's angle, within the make's bounds
     * @return false if the make does not allow it or it is out of bounds (logged)
     */
    public boolean setStartDegrees(double value) {
        if (!canSetDegrees || value < startDegreesMin || value > startDegreesMax) {
            ArLog.log(ArLog.Normal, "%s::setStartDegrees: Cannot set start degrees to %g (%s)", getName(), value,
                    canSetDegrees ? "its bounds are " + startDegreesMin + " to " + startDegreesMax
                            : "this laser chooses its degrees instead");
            return false;
        }
        startDegrees = value;
        return true;
    }

    /** @return the least end angle, degrees */
    public double getEndDegreesMin() {
        return endDegreesMin;
    }

    /** @return the greatest end angle, degrees */
    public double getEndDegreesMax() {
        return endDegreesMax;
    }

    /** @return the angle of the last reading, degrees from the laser's heading (left is positive) */
    public double getEndDegrees() {
        return endDegrees;
    }

    /**
     * @param value the last reading's angle, within the make's bounds
     * @return false if the make does not allow it or it is out of bounds (logged)
     */
    public boolean setEndDegrees(double value) {
        if (!canSetDegrees || value < endDegreesMin || value > endDegreesMax) {
            ArLog.log(ArLog.Normal, "%s::setEndDegrees: Cannot set end degrees to %g (%s)", getName(), value,
                    canSetDegrees ? "its bounds are " + endDegreesMin + " to " + endDegreesMax
                            : "this laser chooses its degrees instead");
            return false;
        }
        endDegrees = value;
        return true;
    }

    /** @return whether the field of view is chosen from a list ({@link #chooseDegrees}) */
    public boolean canChooseDegrees() {
        return degrees.allowed();
    }

    /** @return the field-of-view choices */
    public List<String> getDegreesChoices() {
        return new ArrayList<>(degrees.choices.keySet());
    }

    /** @return the choices, {@code |}-separated, as the options list them */
    public String getDegreesChoicesString() {
        return degrees.choicesString();
    }

    /** @return each choice's field of view, degrees */
    public Map<String, Double> getDegreesChoicesMap() {
        return new LinkedHashMap<>(degrees.choices);
    }

    /**
     * Chooses the field of view: the start and end angles become minus and plus half of it.
     *
     * @param choice one of {@link #getDegreesChoices()}
     * @return false if it is not one (logged)
     */
    public boolean chooseDegrees(String choice) {
        if (!degrees.choose(getName(), choice)) {
            return false;
        }
        startDegrees = -degrees.number() / 2;
        endDegrees = degrees.number() / 2;
        return true;
    }

    /** @return the field of view chosen */
    public String getDegreesChoice() {
        return degrees.choice;
    }

    /** @return the field of view chosen, degrees */
    public double getDegreesChoiceDouble() {
        return degrees.number();
    }

    // ---- increment ----

    /** @return whether the angle between readings may be set within bounds */
    public boolean canSetIncrement() {
        return canSetIncrement;
    }

    /** @return the least angle between readings, degrees */
    public double getIncrementMin() {
        return incrementMin;
    }

    /** @return the greatest angle between readings, degrees */
    public double getIncrementMax() {
        return incrementMax;
    }

    /** @return the angle between readings, degrees */
    public double getIncrement() {
        return canChooseIncrement() ? increment.number() : incrementDegrees;
    }

    /**
     * @param value the angle between readings, within the make's bounds
     * @return false if the make does not allow it or it is out of bounds (logged)
     */
    public boolean setIncrement(double value) {
        if (!canSetIncrement || value < incrementMin || value > incrementMax) {
            ArLog.log(ArLog.Normal, "%s::setIncrement: Cannot set increment to %g (%s)", getName(), value,
                    canSetIncrement ? "its bounds are " + incrementMin + " to " + incrementMax
                            : "this laser chooses its increment instead");
            return false;
        }
        incrementDegrees = value;
        return true;
    }

    /** @return whether the angle between readings is chosen from a list */
    public boolean canChooseIncrement() {
        return increment.allowed();
    }

    /** @return the increment choices */
    public List<String> getIncrementChoices() {
        return new ArrayList<>(increment.choices.keySet());
    }

    /** @return the choices, {@code |}-separated */
    public String getIncrementChoicesString() {
        return increment.choicesString();
    }

    /** @return each choice's angle, degrees */
    public Map<String, Double> getIncrementChoicesMap() {
        return new LinkedHashMap<>(increment.choices);
    }

    /** @param choice one of {@link #getIncrementChoices()} @return false if it is not one (logged) */
    public boolean chooseIncrement(String choice) {
        return increment.choose(getName(), choice);
    }

    /** @return the increment chosen */
    public String getIncrementChoice() {
        return increment.choice;
    }

    /** @return the increment chosen, degrees */
    public double getIncrementChoiceDouble() {
        return increment.number();
    }

    // ---- units, reflector bits, power, baud ----

    /** @return whether the units are chosen from a list */
    public boolean canChooseUnits() {
        return units.allowed();
    }

    /** @return the units choices */
    public List<String> getUnitsChoices() {
        return new ArrayList<>(units.choices.keySet());
    }

    /** @return the choices, {@code |}-separated */
    public String getUnitsChoicesString() {
        return units.choicesString();
    }

    /** @param choice one of {@link #getUnitsChoices()} @return false if it is not one (logged) */
    public boolean chooseUnits(String choice) {
        return units.choose(getName(), choice);
    }

    /** @return the units chosen */
    public String getUnitsChoice() {
        return units.choice;
    }

    /** @return whether the reflector bits are chosen from a list */
    public boolean canChooseReflectorBits() {
        return reflectorBits.allowed();
    }

    /** @return the reflector-bits choices */
    public List<String> getReflectorBitsChoices() {
        return new ArrayList<>(reflectorBits.choices.keySet());
    }

    /** @return the choices, {@code |}-separated */
    public String getReflectorBitsChoicesString() {
        return reflectorBits.choicesString();
    }

    /** @param choice one of {@link #getReflectorBitsChoices()} @return false if it is not one (logged) */
    public boolean chooseReflectorBits(String choice) {
        return reflectorBits.choose(getName(), choice);
    }

    /** @return the reflector bits chosen */
    public String getReflectorBitsChoice() {
        return reflectorBits.choice;
    }

    /** @return whether the laser's power may be switched by the robot */
    public boolean canSetPowerControlled() {
        return canSetPowerControlled;
    }

    /** @param controlled whether the robot switches its power @return false if the make does not allow it */
    public boolean setPowerControlled(boolean controlled) {
        if (!canSetPowerControlled) {
            return false;
        }
        powerControlled = controlled;
        return true;
    }

    /** @return whether the robot switches its power */
    public boolean getPowerControlled() {
        return powerControlled;
    }

    /** @return whether a starting baud rate is chosen (kept; a simulated laser has no serial line) */
    public boolean canChooseStartingBaud() {
        return startingBaud.allowed();
    }

    /** @return the starting-baud choices */
    public List<String> getStartingBaudChoices() {
        return new ArrayList<>(startingBaud.choices.keySet());
    }

    /** @return the choices, {@code |}-separated */
    public String getStartingBaudChoicesString() {
        return startingBaud.choicesString();
    }

    /** @param choice one of the choices @return false if it is not one (logged) */
    public boolean chooseStartingBaud(String choice) {
        return startingBaud.choose(getName(), choice);
    }

    /** @return the starting baud chosen */
    public String getStartingBaudChoice() {
        return startingBaud.choice;
    }

    /** @return whether an auto-baud rate is chosen (kept; a simulated laser has no serial line) */
    public boolean canChooseAutoBaud() {
        return autoBaud.allowed();
    }

    /** @return the auto-baud choices */
    public List<String> getAutoBaudChoices() {
        return new ArrayList<>(autoBaud.choices.keySet());
    }

    /** @return the choices, {@code |}-separated */
    public String getAutoBaudChoicesString() {
        return autoBaud.choicesString();
    }

    /** @param choice one of the choices @return false if it is not one (logged) */
    public boolean chooseAutoBaud(String choice) {
        return autoBaud.choose(getName(), choice);
    }

    /** @return the auto baud chosen */
    public String getAutoBaudChoice() {
        return autoBaud.choice;
    }

    // ---- what a make allows, in its constructor ----

    /** @param defaultChoice the default @param choices each field of view, degrees */
    protected void laserAllowDegreesChoices(String defaultChoice, Map<String, Double> choices) {
        degrees.choices.putAll(choices);
        chooseDegrees(defaultChoice);
    }

    /** The start and end angles may be set within bounds; the defaults are the widest. */
    protected void laserAllowSetDegrees(double startDefault, double startMin, double startMax, double endDefault,
                                        double endMin, double endMax) {
        canSetDegrees = true;
        startDegreesMin = startMin;
        startDegreesMax = startMax;
        startDegrees = startDefault;
        endDegreesMin = endMin;
        endDegreesMax = endMax;
        endDegrees = endDefault;
    }

    /** @param defaultChoice the default @param choices each angle between readings, degrees */
    protected void laserAllowIncrementChoices(String defaultChoice, Map<String, Double> choices) {
        increment.choices.putAll(choices);
        increment.choice = defaultChoice;
    }

    /** The angle between readings may be set within bounds. */
    protected void laserAllowSetIncrement(double defaultIncrement, double min, double max) {
        canSetIncrement = true;
        incrementDegrees = defaultIncrement;
        incrementMin = min;
        incrementMax = max;
    }

    /** @param defaultChoice the default @param choices the units */
    protected void laserAllowUnitsChoices(String defaultChoice, List<String> choices) {
        choices.forEach(c -> units.choices.put(c, null));
        units.choice = defaultChoice;
    }

    /** @param defaultChoice the default @param choices the reflector bits */
    protected void laserAllowReflectorBitsChoices(String defaultChoice, List<String> choices) {
        choices.forEach(c -> reflectorBits.choices.put(c, null));
        reflectorBits.choice = defaultChoice;
    }

    /** @param allowed whether the robot may switch the laser's power */
    protected void laserAllowSetPowerControlled(boolean allowed) {
        canSetPowerControlled = allowed;
    }

    /** @param defaultChoice the default @param choices the starting baud rates */
    protected void laserAllowStartingBaudChoices(String defaultChoice, List<String> choices) {
        choices.forEach(c -> startingBaud.choices.put(c, null));
        startingBaud.choice = defaultChoice;
    }

    /** @param defaultChoice the default @param choices the auto-baud rates */
    protected void laserAllowAutoBaudChoices(String defaultChoice, List<String> choices) {
        choices.forEach(c -> autoBaud.choices.put(c, null));
        autoBaud.choice = defaultChoice;
    }
}
