package robosim.aria;

import java.util.ArrayList;
import java.util.List;
import robosim.protocol.Command;

/**
 * The robot's action handler and the action half of its state reflector, as ARIA's ArRobot.cpp
 * runs them each cycle ("Action Handler" after the sensor-interpretation tasks, then "State
 * Reflector", then the user tasks): the resolver combines the active actions' desires, and the
 * result is sent as velocity, heading and limit commands, each only when it changed or every
 * {@value #REFRESH_MS} ms (ARIA's state reflection refresh time).
 *
 * <p>Direct motion commands and actions take turns as in ARIA: a translational command (setVel,
 * move, setVel2, stop) takes translation from the actions, a rotational one (setRotVel,
 * setHeading, setDeltaHeading, setVel2, stop) takes rotation, for the direct motion precedence time,
 * or until {@link #clearDirectMotion()} when that time is 0 (ARIA's default).
 */
final class ActionDriver {
    /** ARIA's state reflection refresh time: a command the actions want is sent again this often, ms. */
    static final long REFRESH_MS = 500;

    private final ArRobot robot;
    private final List<ArResolver.Entry> actions = new ArrayList<>();
    private ArResolver resolver = new ArPriorityResolver();
    private boolean logActions;
    private final ArActionDesired desired = new ArActionDesired();

    private boolean transDirect;
    private long transSetMs;
    private boolean rotDirect;
    private long rotSetMs;
    private long precedenceMs;

    private boolean actionTransSet;
    private int lastActionTransVal;
    private long lastTransSentMs = Long.MIN_VALUE / 2;
    private boolean actionRotSet;
    private int lastActionRotVal;
    private boolean lastActionRotStopped = true;
    private boolean lastActionRotHeading;
    private long lastRotSentMs = Long.MIN_VALUE / 2;
    private final double[] lastSent = new double[Command.DriveLimit.values().length];
    private double lastSentRotVelMax = Double.NaN;

    ActionDriver(ArRobot robot) {
        this.robot = robot;
        java.util.Arrays.fill(lastSent, Double.NaN);
    }

    // ---- the action list ----

    synchronized boolean add(ArAction action, int priority) {
        if (action == null) {
            ArLogs.info("robot " + robot.getName() + ": addAction was given no action; nothing added");
            return false;
        }
        action.setRobot(robot);
        int at = 0;
        while (at < actions.size() && actions.get(at).priority() > priority) {
            at++;
        }
        actions.add(at, new ArResolver.Entry(priority, action));
        return true;
    }

    synchronized boolean remove(ArAction action) {
        for (int i = 0; i < actions.size(); i++) {
            if (actions.get(i).action() == action) {
                actions.remove(i);
                return true;
            }
        }
        return false;
    }

    synchronized boolean remove(String name) {
        for (int i = actions.size() - 1; i >= 0; i--) {
            if (actions.get(i).action().getName().equals(name)) {
                actions.remove(i);
                return true;
            }
        }
        return false;
    }

    /** The action of that name with the lowest priority, as ARIA's findAction answers. */
    synchronized ArAction find(String name) {
        for (int i = actions.size() - 1; i >= 0; i--) {
            if (actions.get(i).action().getName().equals(name)) {
                return actions.get(i).action();
            }
        }
        return null;
    }

    synchronized List<ArResolver.Entry> entries() {
        return List.copyOf(actions);
    }

    synchronized void deactivateAll() {
        actions.forEach(e -> e.action().deactivate());
    }

    synchronized void setResolver(ArResolver r) {
        resolver = r;
    }

    synchronized ArResolver resolver() {
        return resolver;
    }

    synchronized void setLogActions(boolean on) {
        logActions = on;
    }

    /** @return what the actions wanted at the last cycle, combined (a copy) */
    synchronized boolean logActions() {
        return logActions;
    }

    synchronized ArActionDesired lastDesired() {
        return desired.copy();
    }

    // ---- direct motion ----

    synchronized void directTrans(long nowMs) {
        transDirect = true;
        transSetMs = nowMs;
    }

    synchronized void directRot(long nowMs) {
        rotDirect = true;
        rotSetMs = nowMs;
    }

    /** ARIA's stop: both channels direct, and the actions' last values forgotten. */
    synchronized void stopped(long nowMs) {
        directTrans(nowMs);
        directRot(nowMs);
        forgetActionValues();
    }

    synchronized void clearDirectMotion() {
        transDirect = false;
        rotDirect = false;
        forgetActionValues();
    }

    private void forgetActionValues() {
        lastActionTransVal = 0;
        lastActionRotStopped = true;
        lastActionRotHeading = false;
    }

    synchronized void setPrecedenceMs(long ms) {
        precedenceMs = Math.max(0, ms);
    }

    synchronized long precedenceMs() {
        return precedenceMs;
    }

    synchronized boolean transDirect(long nowMs) {
        return transDirect && (precedenceMs == 0 || nowMs - transSetMs < precedenceMs);
    }

    synchronized boolean rotDirect(long nowMs) {
        return rotDirect && (precedenceMs == 0 || nowMs - rotSetMs < precedenceMs);
    }

    // ---- the cycle ----

    /** Runs the action handler and the state reflector's action part; called in the robot's cycle. */
    synchronized void cycle(long nowMs) {
        if (actions.isEmpty()) {
            return;
        }
        ArActionDesired d = resolver.resolve(List.copyOf(actions), robot, logActions);
        desired.reset();
        desired.merge(d);
        if (!transDirect(nowMs)) {
            reflectTrans(nowMs);
        }
        if (!rotDirect(nowMs)) {
            reflectRot(nowMs);
        }
    }

    private void reflectTrans(long nowMs) {
        limit(Command.DriveLimit.TRANS_ACCEL, desired.getTransAccelStrength(), desired.getTransAccel(),
                robot.getTransAccel());
        limit(Command.DriveLimit.TRANS_DECEL, desired.getTransDecelStrength(), desired.getTransDecel(),
                robot.getTransDecel());
        double robotMax = robot.getTransVelMax();
        double maxVel = strong(desired.getMaxVelStrength()) ? Math.min(desired.getMaxVel(), robotMax) : robotMax;
        double maxNeg = strong(desired.getMaxNegVelStrength())
                ? Math.max(-Math.abs(desired.getMaxNegVel()), -robotMax) : -robotMax;
        int transVal = 0;
        if (strong(desired.getVelStrength())) {
            transVal = ArMath.roundInt(desired.getVel());
            actionTransSet = true;
        }
        transVal = Math.max(ArMath.roundInt(maxNeg), Math.min(ArMath.roundInt(maxVel), transVal));
        if (actionTransSet && (nowMs - lastTransSentMs >= REFRESH_MS || transVal != lastActionTransVal)) {
            robot.send(new Command.SetVel(transVal));
            lastTransSentMs = nowMs;
        }
        lastActionTransVal = transVal;
    }

    private void reflectRot(long nowMs) {
        double absoluteMax = robot.getParameters().maxRVelocity();
        boolean posNeg = strong(desired.getMaxRotVelPosStrength()) || strong(desired.getMaxRotVelNegStrength());
        double maxRotVel = strong(desired.getMaxRotVelStrength()) ? desired.getMaxRotVel() : robot.getRotVelMax();
        maxRotVel = ArMath.roundInt(Math.min(maxRotVel, absoluteMax));
        double lastMax = Double.isNaN(lastSentRotVelMax) ? robot.getRotVelMax() : lastSentRotVelMax;
        if (Math.abs(lastMax - maxRotVel) >= 1) {
            robot.send(new Command.SetMaxRotVel(maxRotVel));
            lastSentRotVelMax = maxRotVel;
        }
        // the Environment has no separate limits by direction: they bound the rotational velocity here
        double maxPos = -1;
        double maxNeg = -1;
        if (posNeg) {
            maxPos = strong(desired.getMaxRotVelPosStrength()) ? Math.min(maxRotVel, desired.getMaxRotVelPos()) : maxRotVel;
            maxNeg = strong(desired.getMaxRotVelNegStrength()) ? Math.min(maxRotVel, desired.getMaxRotVelNeg()) : maxRotVel;
            maxPos = maxPos < 0.5 ? 1 : maxPos;
            maxNeg = maxNeg < 0.5 ? 1 : maxNeg;
        }
        limit(Command.DriveLimit.ROT_ACCEL, desired.getRotAccelStrength(), desired.getRotAccel(), robot.getRotAccel());
        limit(Command.DriveLimit.ROT_DECEL, desired.getRotDecelStrength(), desired.getRotDecel(), robot.getRotDecel());
        boolean rotStopped;
        boolean rotHeading = false;
        int rotVal = 0;
        if (strong(desired.getDeltaHeadingStrength())) {
            rotStopped = ArMath.roundInt(desired.getDeltaHeading()) == 0;
            if (!rotStopped) {
                rotVal = ArMath.roundInt(ArMath.addAngle(desired.getDeltaHeading(), robot.getTh()));
                rotHeading = true;
            }
            actionRotSet = true;
        } else if (strong(desired.getRotVelStrength())) {
            double w = ArMath.roundInt(desired.getRotVel());
            rotStopped = w == 0;
            if (w > 0 && maxPos > -0.5) {
                w = maxPos < 1.1 ? 0 : Math.min(w, maxPos);
            } else if (w < 0 && maxNeg > -0.5) {
                w = maxNeg < 1.1 ? 0 : Math.max(w, -maxNeg);
            }
            rotVal = ArMath.roundInt(w);
            actionRotSet = true;
        } else {
            rotStopped = true;
        }
        if (actionRotSet && (nowMs - lastRotSentMs > REFRESH_MS || rotStopped != lastActionRotStopped
                || rotVal != lastActionRotVal || rotHeading != lastActionRotHeading)) {
            if (rotStopped) {
                robot.send(new Command.SetRotVel(0));
            } else if (rotHeading) {
                robot.send(new Command.SetHeading(robot.encoderHeading(rotVal)));
            } else {
                robot.send(new Command.SetRotVel(rotVal));
            }
            lastRotSentMs = nowMs;
        }
        lastActionRotVal = rotVal;
        lastActionRotStopped = rotStopped;
        lastActionRotHeading = rotHeading;
    }

    /**
     * Sends an acceleration the actions want, or the robot's own again once they stop wanting one,
     * each only when it differs from what was last sent by at least 1 (ARIA's rule).
     */
    private void limit(Command.DriveLimit which, double strength, double wanted, double robotValue) {
        double v = strong(strength) ? ArMath.roundInt(wanted) : robotValue;
        double last = lastSent[which.ordinal()];
        double reference = Double.isNaN(last) ? robotValue : last;
        if (Math.abs(v) > 1 && Math.abs(reference - v) >= 1) {
            robot.send(new Command.SetDriveLimit(which, v));
            lastSent[which.ordinal()] = v;
        }
    }

    private static boolean strong(double strength) {
        return strength >= ArActionDesired.MIN_STRENGTH;
    }
}
