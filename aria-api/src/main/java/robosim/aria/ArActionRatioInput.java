package robosim.aria;

import java.util.ArrayList;
import java.util.LinkedList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Drives from three ratios, as ARIA's {@code ArActionRatioInput} (ArActionRatioInput.cpp):
 * translation and rotation from -100 to 100 (100: full forwards, full left) and a throttle from 0 to
 * 100 scaling both. Inputs ({@link ArRatioInputKeydrive}) set the ratios from fire callbacks, called
 * lowest priority number first, so the highest number's ratios are the ones that count.
 *
 * <p>Each cycle: translation beyond its dead zone (10) asks for ratio × full-throttle speed ×
 * throttle (forwards: the robot's {@code getTransVelMax()} unless set; backwards: a quarter of it
 * unless set), with a rotational velocity (beyond the rotation dead zone, 5) interpolated between the
 * rotation when stopped and the rotation at full speed by how fast the robot goes; inside the dead
 * zone a velocity of 0 and the rotation when stopped. A ratio reversing the robot's motion (beyond
 * 50 the other way) also asks, at the least strength, for three times the robot's deceleration.
 * ARIA's defaults: full throttle 0 (the robot's), rotation 25 deg/s at full speed either way and 50
 * when stopped.
 *
 * <p>Activating an inactive ratio input zeroes the ratios and calls the activate callbacks.
 * Deactivating zeroes them and calls the deactivate callbacks only if it was already inactive: this
 * is ARIA's code as it stands (its check reads {@code if (!isActive())}), kept as ARIA has it. The
 * lateral ratio and parameters go to the desire's lateral channels on robots that move sideways: no
 * simulated robot does, so they are kept and unused.
 */
public class ArActionRatioInput extends ArAction {
    private final ArActionDesired desired = new ArActionDesired();
    private final TreeMap<Integer, List<Runnable>> fireCallbacks = new TreeMap<>();
    private final LinkedList<Runnable> activateCallbacks = new LinkedList<>();
    private final LinkedList<Runnable> deactivateCallbacks = new LinkedList<>();
    private final double transDeadZone = 10;
    private final double rotDeadZone = 5;
    private double fullThrottleForwards;
    private double fullThrottleBackwards;
    private double rotAtFullForwards = 25;
    private double rotAtFullBackwards = 25;
    private double rotAtStopped = 50;
    private double latAtFullForwards;
    private double latAtFullBackwards;
    private double latAtStopped;
    private double transRatio;
    private double rotRatio;
    private double throttleRatio;
    private double latRatio;

    /** ARIA's default name, "RatioInput". */
    public ArActionRatioInput() {
        this("RatioInput");
    }

    /** @param name the action's name */
    public ArActionRatioInput(String name) {
        super(name, "RatioInputs vel and heading");
    }

    /**
     * @param transRatio    -100 (full backwards) to 100 (full forwards)
     * @param rotRatio      -100 (full right) to 100 (full left)
     * @param throttleRatio 0 to 100
     */
    public void setRatios(double transRatio, double rotRatio, double throttleRatio) {
        setRatios(transRatio, rotRatio, throttleRatio, 0);
    }

    /**
     * Each ratio pulled into its range.
     *
     * @param transRatio    -100 (full backwards) to 100 (full forwards)
     * @param rotRatio      -100 (full right) to 100 (full left)
     * @param throttleRatio 0 to 100
     * @param latRatio      -100 to 100 (sideways; no simulated robot moves so)
     */
    public synchronized void setRatios(double transRatio, double rotRatio, double throttleRatio, double latRatio) {
        setTransRatio(transRatio);
        setRotRatio(rotRatio);
        setThrottleRatio(throttleRatio);
        setLatRatio(latRatio);
    }

    /** @param transRatio -100 to 100, pulled into that range */
    public synchronized void setTransRatio(double transRatio) {
        this.transRatio = clamp(transRatio, -100, 100);
    }

    /** @param rotRatio -100 to 100, pulled into that range */
    public synchronized void setRotRatio(double rotRatio) {
        this.rotRatio = clamp(rotRatio, -100, 100);
    }

    /** @param latRatio -100 to 100, pulled into that range */
    public synchronized void setLatRatio(double latRatio) {
        this.latRatio = clamp(latRatio, -100, 100);
    }

    /** @param throttleRatio 0 to 100, pulled into that range */
    public synchronized void setThrottleRatio(double throttleRatio) {
        this.throttleRatio = clamp(throttleRatio, 0, 100);
    }

    private static double clamp(double v, double lo, double hi) {
        return v > hi ? hi : v < lo ? lo : v;
    }

    /** @return the translation ratio */
    public synchronized double getTransRatio() {
        return transRatio;
    }

    /** @return the rotation ratio */
    public synchronized double getRotRatio() {
        return rotRatio;
    }

    /** @return the throttle ratio */
    public synchronized double getThrottleRatio() {
        return throttleRatio;
    }

    /** @return the lateral ratio */
    public synchronized double getLatRatio() {
        return latRatio;
    }

    /**
     * @param priority called in increasing order of priority, so a higher one's ratios win
     * @param callback sets the ratios, called at each firing before they are read
     */
    public synchronized void addFireCallback(int priority, Runnable callback) {
        fireCallbacks.computeIfAbsent(priority, p -> new ArrayList<>()).add(callback);
    }

    /** @param callback a fire callback to remove (logged if it is not there) */
    public synchronized void remFireCallback(Runnable callback) {
        for (Map.Entry<Integer, List<Runnable>> e : fireCallbacks.entrySet()) {
            if (e.getValue().remove(callback)) {
                if (e.getValue().isEmpty()) {
                    fireCallbacks.remove(e.getKey());
                }
                return;
            }
        }
        ArLog.log(ArLog.Normal, "ArActionRatioInput::RemFireCallback: could not remove callback");
    }

    /** @param callback called when an inactive ratio input is activated (last) */
    public void addActivateCallback(Runnable callback) {
        addActivateCallback(callback, ArListPos.LAST);
    }

    /**
     * @param callback called when an inactive ratio input is activated
     * @param position first or last among the others
     */
    public synchronized void addActivateCallback(Runnable callback, int position) {
        if (position == ArListPos.FIRST) {
            activateCallbacks.addFirst(callback);
        } else {
            activateCallbacks.addLast(callback);
        }
    }

    /** @param callback an activate callback to remove */
    public synchronized void remActivateCallback(Runnable callback) {
        activateCallbacks.remove(callback);
    }

    /** @param callback called on deactivating (see the class's note on ARIA's condition) */
    public void addDeactivateCallback(Runnable callback) {
        addDeactivateCallback(callback, ArListPos.LAST);
    }

    /**
     * @param callback called on deactivating (see the class's note on ARIA's condition)
     * @param position first or last among the others
     */
    public synchronized void addDeactivateCallback(Runnable callback, int position) {
        if (position == ArListPos.FIRST) {
            deactivateCallbacks.addFirst(callback);
        } else {
            deactivateCallbacks.addLast(callback);
        }
    }

    /** @param callback a deactivate callback to remove */
    public synchronized void remDeactivateCallback(Runnable callback) {
        deactivateCallbacks.remove(callback);
    }

    /**
     * @param fullThrottleForwards  the speed at full forwards, mm/s (under 1: the robot's maximum)
     * @param fullThrottleBackwards the speed at full backwards, mm/s (under 1: a quarter of it)
     * @param rotAtFullForwards     the rotation at full forwards, deg/s (under 1: half the robot's)
     * @param rotAtFullBackwards    the rotation at full backwards, deg/s (under 1: half the robot's)
     * @param rotAtStopped          the rotation when stopped, deg/s (under 1: the robot's maximum)
     */
    public void setParameters(double fullThrottleForwards, double fullThrottleBackwards, double rotAtFullForwards,
            double rotAtFullBackwards, double rotAtStopped) {
        setParameters(fullThrottleForwards, fullThrottleBackwards, rotAtFullForwards, rotAtFullBackwards, rotAtStopped,
                0, 0, 0);
    }

    /**
     * @param fullThrottleForwards  the speed at full forwards, mm/s
     * @param fullThrottleBackwards the speed at full backwards, mm/s
     * @param rotAtFullForwards     the rotation at full forwards, deg/s
     * @param rotAtFullBackwards    the rotation at full backwards, deg/s
     * @param rotAtStopped          the rotation when stopped, deg/s
     * @param latAtFullForwards     the lateral speed at full forwards, mm/s
     */
    public void setParameters(double fullThrottleForwards, double fullThrottleBackwards, double rotAtFullForwards,
            double rotAtFullBackwards, double rotAtStopped, double latAtFullForwards) {
        setParameters(fullThrottleForwards, fullThrottleBackwards, rotAtFullForwards, rotAtFullBackwards, rotAtStopped,
                latAtFullForwards, 0, 0);
    }

    /**
     * @param fullThrottleForwards  the speed at full forwards, mm/s
     * @param fullThrottleBackwards the speed at full backwards, mm/s
     * @param rotAtFullForwards     the rotation at full forwards, deg/s
     * @param rotAtFullBackwards    the rotation at full backwards, deg/s
     * @param rotAtStopped          the rotation when stopped, deg/s
     * @param latAtFullForwards     the lateral speed at full forwards, mm/s
     * @param latAtFullBackwards    the lateral speed at full backwards, mm/s
     */
    public void setParameters(double fullThrottleForwards, double fullThrottleBackwards, double rotAtFullForwards,
            double rotAtFullBackwards, double rotAtStopped, double latAtFullForwards, double latAtFullBackwards) {
        setParameters(fullThrottleForwards, fullThrottleBackwards, rotAtFullForwards, rotAtFullBackwards, rotAtStopped,
                latAtFullForwards, latAtFullBackwards, 0);
    }

    /**
     * @param fullThrottleForwards  the speed at full forwards, mm/s
     * @param fullThrottleBackwards the speed at full backwards, mm/s
     * @param rotAtFullForwards     the rotation at full forwards, deg/s
     * @param rotAtFullBackwards    the rotation at full backwards, deg/s
     * @param rotAtStopped          the rotation when stopped, deg/s
     * @param latAtFullForwards     the lateral speed at full forwards, mm/s
     * @param latAtFullBackwards    the lateral speed at full backwards, mm/s
     * @param latAtStopped          the lateral speed when stopped, mm/s
     */
    public synchronized void setParameters(double fullThrottleForwards, double fullThrottleBackwards,
            double rotAtFullForwards, double rotAtFullBackwards, double rotAtStopped, double latAtFullForwards,
            double latAtFullBackwards, double latAtStopped) {
        String n = getName();
        this.fullThrottleForwards = ActionArgs.finite(n, "fullThrottleForwards", fullThrottleForwards);
        this.fullThrottleBackwards = ActionArgs.finite(n, "fullThrottleBackwards", fullThrottleBackwards);
        this.rotAtFullForwards = ActionArgs.finite(n, "rotAtFullForwards", rotAtFullForwards);
        this.rotAtFullBackwards = ActionArgs.finite(n, "rotAtFullBackwards", rotAtFullBackwards);
        this.rotAtStopped = ActionArgs.finite(n, "rotAtStopped", rotAtStopped);
        this.latAtFullForwards = ActionArgs.finite(n, "latAtFullForwards", latAtFullForwards);
        this.latAtFullBackwards = ActionArgs.finite(n, "latAtFullBackwards", latAtFullBackwards);
        this.latAtStopped = ActionArgs.finite(n, "latAtStopped", latAtStopped);
    }

    @Override
    public void activate() {
        List<Runnable> run = List.of();
        synchronized (this) {
            if (!isActive()) {
                transRatio = rotRatio = throttleRatio = latRatio = 0;
                run = List.copyOf(activateCallbacks);
            }
        }
        run.forEach(Runnable::run);
        super.activate();
    }

    @Override
    public void deactivate() {
        List<Runnable> run = List.of();
        synchronized (this) {
            if (!isActive()) { // ARIA's condition, as it stands
                transRatio = rotRatio = throttleRatio = latRatio = 0;
                run = List.copyOf(deactivateCallbacks);
            }
        }
        run.forEach(Runnable::run);
        super.deactivate();
    }

    @Override
    public ArActionDesired fire(ArActionDesired currentDesired) {
        List<Runnable> callbacks = new ArrayList<>();
        synchronized (this) {
            fireCallbacks.values().forEach(callbacks::addAll);
        }
        callbacks.forEach(Runnable::run);
        synchronized (this) {
            desired.reset();
            double fullForwards = fullThrottleForwards < 1 ? myRobot.getTransVelMax() : fullThrottleForwards;
            double fullBackwards = fullThrottleBackwards < 1 ? myRobot.getTransVelMax() / 4 : fullThrottleBackwards;
            double rotForwards = rotAtFullForwards < 1 ? myRobot.getRotVelMax() / 2 : rotAtFullForwards;
            double rotBackwards = rotAtFullBackwards < 1 ? myRobot.getRotVelMax() / 2 : rotAtFullBackwards;
            double rotStopped = rotAtStopped < 1 ? myRobot.getRotVelMax() : rotAtStopped;
            double throttle = throttleRatio / 100.0;
            if (transRatio > transDeadZone || transRatio < -transDeadZone) {
                boolean forwards = transRatio > 0;
                desired.setVel(transRatio / 100.0 * (forwards ? fullForwards : fullBackwards) * throttle);
                double speedRatio = Math.abs(myRobot.getVel() / fullForwards);
                double rotFull = forwards ? rotForwards : rotBackwards;
                desired.setRotVel(Math.abs(rotRatio) < rotDeadZone ? 0
                        : rotRatio / 100.0 * ((rotFull - rotStopped) * speedRatio + rotStopped) * throttle);
            } else {
                desired.setVel(0);
                desired.setRotVel(Math.abs(rotRatio) < rotDeadZone ? 0 : rotRatio / 100.0 * rotStopped * throttle);
            }
            double vel = myRobot.getVel();
            if ((vel > 0 && transRatio < -50) || (vel < 0 && transRatio > 50)) {
                desired.setTransDecel(myRobot.getTransDecel() * 3, ArActionDesired.MIN_STRENGTH);
            }
            double rotVel = myRobot.getRotVel();
            if ((rotVel > 0 && rotRatio < -50) || (rotVel < 0 && rotRatio > 50)) {
                desired.setRotDecel(myRobot.getRotDecel() * 3, ArActionDesired.MIN_STRENGTH);
            }
            return desired;
        }
    }

    @Override
    public synchronized ArActionDesired getDesired() {
        return desired;
    }
}
