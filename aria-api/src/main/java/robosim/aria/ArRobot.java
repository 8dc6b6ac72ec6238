package robosim.aria;

import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import robosim.params.RobotParameterFiles;
import robosim.protocol.Command;
import robosim.protocol.RobotParameters;
import robosim.protocol.RobotState;

/**
 * The Pioneer Robot-Object, with ARIA's {@code ArRobot} semantics (see docs/ARIA-SEMANTICS.md): units
 * mm, mm/s, degrees, deg/s; motion calls do not block; getters answer from the latest state the
 * Environment reported, which changes only while the robot's code is yielded (in
 * {@link ArUtil#sleep}), so a program reads a consistent snapshot.
 *
 * <pre>{@code
 * ArRobot robot = new ArRobot(name, host, port, "p3dx");
 * if (!robot.blockingConnect()) return;
 * robot.enableMotors();
 * robot.move(1000);
 * while (!robot.isMoveDone()) ArUtil.sleep(100);
 * robot.disconnect();
 * }</pre>
 */
public class ArRobot extends ArRobotPose {
    /** ARIA's default for {@link #isMoveDone(double)}, mm. */
    public static final double DEFAULT_MOVE_DONE = 40;
    /** ARIA's default for {@link #isHeadingDone(double)}, degrees. */
    public static final double DEFAULT_HEADING_DONE = 3;
    /** ARIA's {@code isStopped} translational threshold, mm/s. */
    public static final double STOPPED_VEL = 4;
    /** ARIA's {@code isStopped} rotational threshold, deg/s. */
    public static final double STOPPED_ROT_VEL = 1;
    private volatile ArKeyHandler keyHandler;
    private volatile boolean keyHandlerUseExitNotShutdown = true;
    private final java.util.concurrent.ConcurrentSkipListMap<Integer, ArLaser> lasers =
            new java.util.concurrent.ConcurrentSkipListMap<>();
    private volatile ArPose moveStart;
    private volatile double moveDistance;
    private volatile Double headingTarget;
    private volatile double maxTransVel;
    private final DriveLimits driveLimits = new DriveLimits();
    private volatile double moveDoneDist = DEFAULT_MOVE_DONE;
    private volatile double headingDoneDiff = DEFAULT_HEADING_DONE;
    private volatile double maxRotVel;
    /** The absolute maxima, the negative velocity limit and the lateral limits. */
    private final Maxima maxima = new Maxima();
    private volatile double transAsked;
    private volatile double rotAsked;
    private volatile ArPTZ ptz;

    /**
     * A robot as ARIA's {@code ArRobot robot;} makes one, named {@code robot} (the second such robot
     * of the program {@code robot2}, and so on, as ARIA names them), a Pioneer 3-DX ({@code p3dx}),
     * to be connected by an {@link ArRobotConnector} or {@link ArSimpleConnector}, which say where
     * from the command line.
     */
    public ArRobot() {
        this(defaultName());
    }

    /**
     * A robot as ARIA's {@code ArRobot robot(name);} makes one, a Pioneer 3-DX ({@code p3dx}), to be
     * connected by an {@link ArRobotConnector} or {@link ArSimpleConnector}.
     *
     * @param name the robot's name; in a RoboSim world, the connector's command line may give another
     */
    public ArRobot(String name) {
        this(name, ArRobotConnector.DEFAULT_HOST, ArRobotConnector.DEFAULT_PORT, "p3dx");
    }

    /**
     * @param name      the robot's name in the world
     * @param host      the Environment's host
     * @param port      the Environment's robot port
     * @param paramFile the robot's parameter file: a path, or a shipped name such as {@code p3dx}
     */
    public ArRobot(String name, String host, int port, String paramFile) {
        this(name, host, port, RobotParameterFiles.load(paramFile));
        this.bumpers = RobotParameterFiles.bumpers(paramFile);
        this.sonarCycleMs = RobotParameterFiles.sonarCycle(paramFile);
        this.wheelEncoders = new WheelEncoders(RobotParameterFiles.conversionFactors(paramFile).distConvFactor());
    }

    /**
     * @param name       the robot's name in the world
     * @param host       the Environment's host
     * @param port       the Environment's robot port
     * @param parameters the robot's parameters; the robot has no bump rings (ARIA's default), as
     *                   these are read from a parameter file's bumper keys
     */
    public ArRobot(String name, String host, int port, RobotParameters parameters) {
        super(name, host, port, parameters);
        useParameters(parameters);
    }

    /**
     * Renames the robot and says where it connects, before it connects, with the parameters given.
     *
     * @throws IllegalStateException if the robot is connected
     */
    @Override
    protected void relocate(String name, String host, int port, RobotParameters parameters) {
        super.relocate(name, host, port, parameters);
        useParameters(parameters);
    }

    // ---- connection callbacks and waits ----

    /** @return the run-exit callbacks, in order (a copy) */
    public List<Runnable> getRunExitListCopy() {
        return events.runExit.copy();
    }

    /** The states ARIA's waits end in. */
    public enum WaitState {
        /** The robot has connected. */
        WAIT_CONNECTED,
        /** The robot failed to connect. */
        WAIT_FAILED_CONN,
        /** The robot's cycle has stopped. */
        WAIT_RUN_EXIT,
        /** The wait reached its time limit. */
        WAIT_TIMEDOUT,
        /** The waiting thread was interrupted. */
        WAIT_INTR,
        /** The wait failed. */
        WAIT_FAIL
    }

    // ---- actions ----

    /**
     * Adds an action, fired each cycle by the resolver (ARIA's {@code addAction}): higher priorities
     * fire first and get the strength they want; see {@link ArPriorityResolver}. Actions drive the
     * robot only while no direct motion command holds it: a direct command (setVel, move, setRotVel,
     * setHeading, setVel2, stop) takes its channel from the actions until {@link #clearDirectMotion()}
     * (or for {@link #setDirectMotionPrecedenceTime} ms), as in ARIA.
     *
     * @param action   the action; its robot becomes this one
     * @param priority its priority (ARIA's examples use 0..100)
     * @return false if the action is null
     */
    public boolean addAction(ArAction action, int priority) {
        return actions.add(action, priority);
    }

    /** @param action an action to remove @return whether it was there */
    public boolean remAction(ArAction action) {
        return actions.remove(action);
    }

    /** @param actionName the name of an action to remove (the one of lowest priority) @return whether one was there */
    public boolean remAction(String actionName) {
        return actions.remove(actionName);
    }

    /** @param actionName an action's name @return the action of that name with the lowest priority, or null */
    public ArAction findAction(String actionName) {
        return actions.find(actionName);
    }

    /** @return the actions with their priorities, in firing order (highest priority first) */
    public List<ArResolver.Entry> getActionList() {
        return actions.entries();
    }

    /** Deactivates every action of the robot (they stay added). */
    public void deactivateActions() {
        actions.deactivateAll();
    }

    /** @param resolver the resolver that combines the actions (an {@link ArPriorityResolver} by default) */
    public void setResolver(ArResolver resolver) {
        actions.setResolver(java.util.Objects.requireNonNull(resolver, "resolver"));
    }

    /** @return the resolver that combines the actions */
    public ArResolver getResolver() {
        return actions.resolver();
    }

    /** @param on whether each cycle logs every action's desire (ARIA's {@code setLogActions}) */
    public void setLogActions(boolean on) {
        actions.setLogActions(on);
    }

    /** @return what the actions wanted at the last cycle, combined (a copy) */
    public ArActionDesired getActionDesired() {
        return actions.lastDesired();
    }

    /** @return what the resolver gave at the last cycle: ARIA's name for {@link #getActionDesired()} */
    public ArActionDesired getLastActionResolverOutput() {
        return getActionDesired();
    }

    /** @return the actions with their priorities, highest first: ARIA's action map, as {@link #getActionList()} */
    public List<ArResolver.Entry> getActionMap() {
        return getActionList();
    }

    /** Logs the active actions by priority, highest first, as ARIA's {@code logActions()}. */
    public void logActions() {
        logActions(false);
    }

    /**
     * Logs the actions by priority, highest first, as ARIA's {@code ArRobot::logActions} (ArRobot.cpp): a
     * priority line, then each action's name.
     *
     * @param logDeactivated whether the deactivated actions are listed too
     */
    public void logActions(boolean logDeactivated) {
        StringBuilder b = new StringBuilder(logDeactivated
                ? "The action list (" + getActionList().size() + " total):" : "The active action list:");
        Integer last = null;
        for (ArResolver.Entry e : getActionList()) {
            if (!logDeactivated && !e.action().isActive()) {
                continue;
            }
            if (last == null || last != e.priority()) {
                b.append("\nPriority ").append(e.priority()).append(':');
                last = e.priority();
            }
            b.append("\n  ").append(e.action().getName()).append(e.action().isActive() ? "" : " (deactivated)");
        }
        LOG.info(() -> "robot " + getName() + ": " + b);
    }

    /** @return whether each cycle logs every action's desire ({@link #setLogActions}) */
    public boolean getLogActions() {
        return actions.logActions();
    }

    /**
     * @param ptz the robot's camera, for ARIA's {@code ArRobot::getPTZ} (ArRobot.h; an {@link ArPTZ}
     *     is given the robot when made)
     */
    public void setPTZ(ArPTZ ptz) {
        this.ptz = ptz;
    }

    /** @return the camera given to {@link #setPTZ}, or null */
    public ArPTZ getPTZ() {
        return ptz;
    }

    /**
     * Gives motion back to the actions after direct motion commands, and forgets the actions' last
     * values so that what they want is sent again (ARIA's {@code clearDirectMotion}).
     */
    public void clearDirectMotion() {
        actions.clearDirectMotion();
    }

    /**
     * @param ms how long a direct motion command keeps its channel from the actions, simulated ms;
     *           0 (ARIA's default) means until {@link #clearDirectMotion()}
     */
    public void setDirectMotionPrecedenceTime(int ms) {
        actions.setPrecedenceMs(ms);
    }

    /** @return how long a direct motion command keeps its channel from the actions, ms; 0 means until cleared */
    public long getDirectMotionPrecedenceTime() {
        return actions.precedenceMs();
    }

    /** @return whether a direct motion command holds translation or rotation now */
    public boolean isDirectMotion() {
        long now = simulatedMs();
        return actions.transDirect(now) || actions.rotDirect(now);
    }

    /**
     * Whether the robot is trying to move, as ARIA's state reflection decides it each cycle: a
     * velocity asked of more than 0.5 mm/s or deg/s (directly or by the actions), a move not yet
     * done, a heading more than 1° away; or {@link #forceTryingToMove()} in this cycle.
     *
     * @return whether the robot is trying to move
     */
    public boolean isTryingToMove() {
        if (forcedTryingToMove) {
            return true;
        }
        long now = simulatedMs();
        boolean trans;
        if (actions.transDirect(now)) {
            trans = moveStart != null ? !isMoveDone() : transAsked > 0.5;
        } else {
            ArActionDesired d = actions.lastDesired();
            trans = d.getVelStrength() > 0 && Math.abs(d.getVel()) > 0.5;
        }
        boolean rot;
        if (actions.rotDirect(now)) {
            Double target = headingTarget;
            rot = target != null ? Math.abs(ArMath.subAngle(getTh(), target)) > 1 : rotAsked > 0.5;
        } else {
            ArActionDesired d = actions.lastDesired();
            rot = d.getRotVelStrength() > 0 && Math.abs(d.getRotVel()) > 0.5
                    || d.getDeltaHeadingStrength() > 0 && Math.abs(d.getDeltaHeading()) > 1;
        }
        return trans || rot;
    }

    /**
     * Makes {@link #isTryingToMove()} true until the end of the current cycle, as ARIA's {@code
     * ArRobot::forceTryingToMove} (ArRobot.h).
     */
    public void forceTryingToMove() {
        forcedTryingToMove = true;
    }

    /**
     * @return the state reflection's refresh time, ms (ARIA's default 500): ARIA resends an unchanged
     *         motion command this often; the Environment keeps a command until the next, so nothing is
     *         resent here
     */
    public int getStateReflectionRefreshTime() {
        return extras.refreshMs;
    }

    /** @param msec the refresh time, ms; below 0 means 0, as in ARIA */
    public void setStateReflectionRefreshTime(int msec) {
        extras.refreshMs = Math.max(0, msec);
    }

    // ---- range devices ----

    /** @param device a range device to attach; its robot becomes this one */
    public void addRangeDevice(ArRangeDevice device) {
        rangeDevices.add(device, this);
    }

    /** @param device a range device to detach; its robot is cleared */
    public void remRangeDevice(ArRangeDevice device) {
        rangeDevices.remove(device);
    }

    /** @param name a device's name @return the first attached device of that name, or null */
    public ArRangeDevice findRangeDevice(String name) {
        return rangeDevices.find(name);
    }

    /** @return the attached range devices */
    public List<ArRangeDevice> getRangeDeviceList() {
        return rangeDevices.list();
    }

    // ---- direct commands (ARIA's com, comInt, com2Bytes, comStr) ----

    /**
     * Sends a command with no argument, as ARIA's {@code com}: see {@link #comInt(int, int)}.
     *
     * @param command one of {@link ArCommands}
     * @return whether it is one the simulation carries out (else logged and ignored)
     */
    public boolean com(int command) {
        return comInt(command, 0);
    }

    /**
     * Sends a Pioneer command with an integer argument, as an ARIA program sends one directly. The
     * simulation carries out the motion and device commands by the calls that do the same:
     * {@code ENABLE} ({@link #enableMotors}/{@link #disableMotors}), {@code SETA} and {@code SETRA}
     * (acceleration, or deceleration when negative), {@code SETV}, {@code SETRV}, {@code SETO}
     * (odometry to 0, 0, 0), {@code MOVE}, {@code VEL}, {@code RVEL}, {@code ROTATE}, {@code HEAD},
     * {@code DHEAD}, {@code DCHEAD}, {@code STOP}, {@code VEL2} (left and right bytes, 2 cm/s each),
     * {@code SONAR}; {@code PULSE}, {@code SOUNDTOG}, {@code SOUND}, {@code SAY} and {@code PLAYLIST}
     * are taken and do nothing (the simulated robot has no sound). Another command is logged and
     * ignored.
     *
     * @param command one of {@link ArCommands}
     * @param arg     its argument, a signed 16-bit value as the packet carries it
     * @return whether the simulation carries it out
     */
    public boolean comInt(int command, int arg) {
        short v = (short) arg;
        switch (command) {
            case ArCommands.ENABLE -> {
                if (v != 0) {
                    enableMotors();
                } else {
                    disableMotors();
                }
            }
            case ArCommands.SETA -> {
                if (v >= 0) {
                    setTransAccel(v);
                } else {
                    setTransDecel(-v);
                }
            }
            case ArCommands.SETRA -> {
                if (v >= 0) {
                    setRotAccel(v);
                } else {
                    setRotDecel(-v);
                }
            }
            case ArCommands.SETV -> setTransVelMax(v);
            case ArCommands.SETRV -> setRotVelMax(v);
            case ArCommands.SETO -> moveTo(new ArPose());
            case ArCommands.MOVE -> move(v);
            case ArCommands.VEL -> setVel(v);
            case ArCommands.RVEL, ArCommands.ROTATE -> setRotVel(v);
            case ArCommands.HEAD -> setHeading(v);
            case ArCommands.DHEAD, ArCommands.DCHEAD -> setDeltaHeading(v);
            case ArCommands.STOP -> stop();
            case ArCommands.VEL2 -> setVel2(20.0 * (byte) (v >> 8), 20.0 * (byte) v);
            case ArCommands.SONAR -> {
                if (v != 0) {
                    enableSonar();
                } else {
                    disableSonar();
                }
            }
            case ArCommands.PULSE, ArCommands.SOUNDTOG, ArCommands.SOUND, ArCommands.SAY, ArCommands.PLAYLIST -> {
                // the simulated robot keeps its own connection and has no sound
            }
            default -> {
                ArLog.log(ArLog.Normal, "ArRobot::comInt: command %d is not simulated; ignored", command);
                return false;
            }
        }
        return true;
    }

    /**
     * Sends a command with two bytes, as ARIA's {@code com2Bytes}: the high byte first, as
     * {@link #comInt(int, int)} takes them.
     *
     * @param command one of {@link ArCommands}
     * @param high    the first byte
     * @param low     the second byte
     * @return whether the simulation carries it out
     */
    public boolean com2Bytes(int command, int high, int low) {
        return comInt(command, ((high & 0xff) << 8) | (low & 0xff));
    }

    /**
     * Sends a command with a string, as ARIA's {@code comStr}: only {@code SAY} takes one, and the
     * simulated robot has no sound.
     *
     * @param command one of {@link ArCommands}
     * @param text    the string
     * @return whether the simulation carries it out
     */
    public boolean comStr(int command, String text) {
        if (command == ArCommands.SAY) {
            return true;
        }
        ArLog.log(ArLog.Normal, "ArRobot::comStr: command %d is not simulated; ignored", command);
        return false;
    }

    // ---- the key handler ----

    /**
     * Checks the handler's keys each cycle, as a sensor-interpretation task ({@code Key Handler},
     * position 50); Escape exits the program ({@link Aria#exit}), as ARIA's {@code attachKeyHandler}.
     *
     * @param handler the key handler
     */
    public void attachKeyHandler(ArKeyHandler handler) {
        attachKeyHandler(handler, true, true);
    }

    /**
     * @param handler            the key handler
     * @param exitOnEscape       whether Escape ends the program
     * @param useExitNotShutdown whether it ends by {@link Aria#exit} (else the robot stops running
     *                           and {@link Aria#shutdown})
     */
    public void attachKeyHandler(ArKeyHandler handler, boolean exitOnEscape, boolean useExitNotShutdown) {
        keyHandler = handler;
        keyHandlerUseExitNotShutdown = useExitNotShutdown;
        addSensorInterpTask("Key Handler", 50, handler::checkKeys);
        if (exitOnEscape) {
            handler.addKeyHandler(ArKeyHandler.ESCAPE, this::keyHandlerExit);
        }
    }

    /**
     * What Escape does on an attached key handler, as ARIA's {@code ArRobot::keyHandlerExit}
     * (ArRobot.cpp): logs that Escape was pressed, then ends the program with {@link Aria#exit}, or,
     * if the handler was attached with {@code useExitNotShutdown} false, stops the robot's cycle and
     * {@link Aria#shutdown}s.
     */
    public void keyHandlerExit() {
        ArLog.log(ArLog.Terse, "Escape was pressed, program is exiting.");
        if (keyHandlerUseExitNotShutdown) {
            Aria.exit(0);
        } else {
            stopRunning();
            Aria.shutdown();
        }
    }

    /** @return the key handler attached, or null */
    public ArKeyHandler getKeyHandler() {
        return keyHandler;
    }

    // ---- lasers, by number (ARIA's laser map) ----

    /**
     * Adds a laser as its number on the robot, and as a range device, as ARIA's
     * {@code ArRobot::addLaser} (ArRobot.cpp).
     *
     * @param laser  the laser
     * @param number its number, from 1
     * @return false if another laser has the number (logged); true if added or already there
     */
    public boolean addLaser(ArLaser laser, int number) {
        return addLaser(laser, number, true);
    }

    /**
     * @param laser            the laser
     * @param number           its number
     * @param addAsRangeDevice whether it becomes a range device of the robot too
     * @return false if the laser is null or another has the number (logged)
     */
    public boolean addLaser(ArLaser laser, int number, boolean addAsRangeDevice) {
        if (laser == null) {
            ArLog.log(ArLog.Normal, "ArRobot::addLaser: Tried to add NULL laser as laser number %d", number);
            return false;
        }
        ArLaser there = lasers.putIfAbsent(number, laser);
        if (there != null && there != laser) {
            ArLog.log(ArLog.Normal, "ArRobot::addLaser: Tried to add laser %s as laser number %d but there is already"
                    + " a laser of that number (called %s)", laser.getName(), number, there.getName());
            return false;
        }
        if (addAsRangeDevice) {
            remRangeDevice(laser);
            addRangeDevice(laser);
        } else {
            laser.setRobot(this);
        }
        return true;
    }

    /** @param laser a laser to remove, and as a range device @return false if it is not the robot's (logged) */
    public boolean remLaser(ArLaser laser) {
        return remLaser(laser, true);
    }

    /**
     * @param laser               a laser to remove
     * @param removeAsRangeDevice whether it stops being a range device too
     * @return false if it is not the robot's (logged)
     */
    public boolean remLaser(ArLaser laser, boolean removeAsRangeDevice) {
        for (var e : lasers.entrySet()) {
            if (e.getValue() == laser) {
                lasers.remove(e.getKey());
                if (removeAsRangeDevice) {
                    remRangeDevice(laser);
                }
                return true;
            }
        }
        ArLog.log(ArLog.Normal, "ArRobot::remLaser: Could not find laser %s to remove",
                laser == null ? "NULL" : laser.getName());
        return false;
    }

    /** @param number a laser's number @return false if the robot has none of that number (logged) */
    public boolean remLaser(int number) {
        ArLaser laser = lasers.get(number);
        if (laser == null) {
            ArLog.log(ArLog.Normal, "ArRobot::remLaser: Could not find laser %d to remove", number);
            return false;
        }
        return remLaser(laser, true);
    }

    /** @param number a laser's number @return the laser, or null */
    public ArLaser findLaser(int number) {
        return lasers.get(number);
    }

    /** @return the lasers by number, ascending; a copy */
    public java.util.SortedMap<Integer, ArLaser> getLaserMap() {
        return new java.util.TreeMap<>(lasers);
    }

    /** @param laser a laser @return whether it is one of the robot's */
    public boolean hasLaser(ArLaser laser) {
        return lasers.containsValue(laser);
    }

    /** @return how many lasers the robot has */
    public int getNumLasers() {
        return lasers.size();
    }

    /** @param name the name of a range device to detach (the first of that name) */
    public void remRangeDevice(String name) {
        ArRangeDevice d = rangeDevices.find(name);
        if (d != null) {
            rangeDevices.remove(d);
        }
    }

    /** @param device a range device @return whether it is attached */
    public boolean hasRangeDevice(ArRangeDevice device) {
        return rangeDevices.list().contains(device);
    }

    /**
     * @return the attached range devices, in the order attached (ARIA's {@code
     *     ArRobot::getRangeDevices} (ArRobot.h))
     */
    public List<ArRangeDevice> getRangeDevices() {
        return rangeDevices.list();
    }

    /** @return the latest state, for the devices of this package */
    RobotState currentState() {
        return state();
    }

    /** @param command a request sent with this cycle's requests, for the devices of this package */
    void send(Command command) {
        request(command);
    }

    // ---- motion: none of these block ----

    /**
     * Travels a distance from the current pose; negative is backwards.
     *
     * @param distance mm
     * @throws IllegalArgumentException if it is not finite
     */
    public void move(double distance) {
        Command.Move move = new Command.Move(distance);
        moveStart = getPose();
        moveDistance = distance;
        transAsked = 0;
        request(move);
        actions.directTrans(simulatedMs());
    }

    /** Translational and rotational velocity to zero at once. */
    public void stop() {
        moveStart = null;
        headingTarget = null;
        transAsked = 0;
        rotAsked = 0;
        request(new Command.Stop());
        actions.stopped(simulatedMs());
    }

    /**
     * @param velocity mm/s, rounded and clamped to the maximum translational velocity, and backwards
     *                 to {@link #getTransNegVelMax()}, as ARIA's state reflection clamps it
     * @throws IllegalArgumentException if it is not finite
     */
    public void setVel(double velocity) {
        Command.SetVel vel = new Command.SetVel(Math.rint(Math.max(velocity, maxima.transNegVelMax())));
        moveStart = null;
        transAsked = Math.abs(vel.vel());
        request(vel);
        actions.directTrans(simulatedMs());
    }

    /**
     * @param velocity deg/s, counter-clockwise positive, clamped to the maximum rotational velocity
     * @throws IllegalArgumentException if it is not finite
     */
    public void setRotVel(double velocity) {
        Command.SetRotVel rotVel = new Command.SetRotVel(velocity);
        headingTarget = null;
        rotAsked = Math.abs(velocity);
        request(rotVel);
        actions.directRot(simulatedMs());
    }

    /**
     * Sets the wheel velocities; cancels any rotation command.
     *
     * @param leftVelocity  mm/s
     * @param rightVelocity mm/s
     * @throws IllegalArgumentException if either is not finite
     */
    public void setVel2(double leftVelocity, double rightVelocity) {
        Command.SetVel2 vel2 = new Command.SetVel2(leftVelocity, rightVelocity);
        moveStart = null;
        headingTarget = null;
        transAsked = Math.max(Math.abs(leftVelocity), Math.abs(rightVelocity));
        rotAsked = 0;
        request(vel2);
        actions.directTrans(simulatedMs());
        actions.directRot(simulatedMs());
    }

    /**
     * @param heading absolute heading to turn to, degrees
     * @throws IllegalArgumentException if it is not finite
     */
    public void setHeading(double heading) {
        Command.SetHeading turn = new Command.SetHeading(heading);
        headingTarget = ArMath.fixAngle(heading);
        request(new Command.SetHeading(encoderHeading(heading)));
        actions.directRot(simulatedMs());
    }

    /**
     * @param delta degrees to turn from the current heading
     * @throws IllegalArgumentException if it is not finite
     */
    public void setDeltaHeading(double delta) {
        Command.SetDeltaHeading turn = new Command.SetDeltaHeading(delta);
        headingTarget = ArMath.fixAngle(getTh() + delta);
        request(turn);
        actions.directRot(simulatedMs());
    }

    /**
     * @param velocity new translational limit, mm/s, within the parameter file's maximum
     * @throws IllegalArgumentException if it is not finite
     */
    public void setMaxTransVel(double velocity) {
        Command.SetMaxTransVel limit = new Command.SetMaxTransVel(Math.min(velocity, getAbsoluteMaxTransVel()));
        maxTransVel = Math.max(0, Math.min(velocity, getAbsoluteMaxTransVel()));
        request(limit);
    }

    /**
     * @param velocity new rotational limit, deg/s, within the parameter file's maximum
     * @throws IllegalArgumentException if it is not finite
     */
    public void setMaxRotVel(double velocity) {
        Command.SetMaxRotVel limit = new Command.SetMaxRotVel(Math.min(velocity, getAbsoluteMaxRotVel()));
        maxRotVel = Math.max(0, Math.min(velocity, getAbsoluteMaxRotVel()));
        request(limit);
    }

    /** @return the translational limit, mm/s */
    public double getMaxTransVel() {
        return maxTransVel;
    }

    /**
     * ARIA's name for the translational velocity limit: as {@link #setMaxTransVel}, except that a
     * value of 0 or less is ignored with a log line, as ARIA's {@code setTransVelMax} ignores it (the
     * original RoboSim's {@code setMaxTransVel} sets a zero limit).
     *
     * @param vel the new limit, mm/s; capped at {@link #getAbsoluteMaxTransVel()} with ARIA's log line
     */
    public void setTransVelMax(double vel) {
        if (!DriveLimits.ignoresVelocity("setTransVelMax", vel, getName())) {
            double abs = getAbsoluteMaxTransVel();
            if (vel > abs) {
                LOG.warning(() -> "robot " + getName() + ": ArRobot: setTransVelMax of " + vel
                        + " is over the absolute max vel of " + abs + ", capping it");
            }
            setMaxTransVel(vel);
        }
    }

    /** @return the translational velocity limit, mm/s (ARIA's name for {@link #getMaxTransVel}) */
    public double getTransVelMax() {
        return getMaxTransVel();
    }

    /**
     * ARIA's name for the rotational velocity limit; a value of 0 or less is ignored with a log line.
     *
     * @param vel the new limit, deg/s; capped at {@link #getAbsoluteMaxRotVel()} with ARIA's log line
     */
    public void setRotVelMax(double vel) {
        if (!DriveLimits.ignoresVelocity("setRotVelMax", vel, getName())) {
            double abs = getAbsoluteMaxRotVel();
            if (vel > abs) {
                LOG.warning(() -> "robot " + getName() + ": ArRobot: setRotVelMax of " + vel
                        + " is over the absolute max vel of " + abs + ", capping it");
            }
            setMaxRotVel(vel);
        }
    }

    /** @return the rotational velocity limit, deg/s (ARIA's name for {@link #getMaxRotVel}) */
    public double getRotVelMax() {
        return getMaxRotVel();
    }

    /** @param acc the translational acceleration, mm/s²; 0 or less is ignored, as in ARIA */
    public void setTransAccel(double acc) {
        setDriveLimit(Command.DriveLimit.TRANS_ACCEL, acc);
    }

    /** @param decel the translational deceleration, mm/s²; 0 or less is ignored, as in ARIA */
    public void setTransDecel(double decel) {
        setDriveLimit(Command.DriveLimit.TRANS_DECEL, decel);
    }

    /** @param acc the rotational acceleration, deg/s²; 0 or less is ignored, as in ARIA */
    public void setRotAccel(double acc) {
        setDriveLimit(Command.DriveLimit.ROT_ACCEL, acc);
    }

    /** @param decel the rotational deceleration, deg/s²; 0 or less is ignored, as in ARIA */
    public void setRotDecel(double decel) {
        setDriveLimit(Command.DriveLimit.ROT_DECEL, decel);
    }

    /** @return the translational acceleration in force, mm/s² (the parameter file's until set) */
    public double getTransAccel() {
        return driveLimits.get(Command.DriveLimit.TRANS_ACCEL, getParameters());
    }

    /** @return the translational deceleration in force, mm/s² (the parameter file's until set) */
    public double getTransDecel() {
        return driveLimits.get(Command.DriveLimit.TRANS_DECEL, getParameters());
    }

    /** @return the rotational acceleration in force, deg/s² (the parameter file's until set) */
    public double getRotAccel() {
        return driveLimits.get(Command.DriveLimit.ROT_ACCEL, getParameters());
    }

    /** @return the rotational deceleration in force, deg/s² (the parameter file's until set) */
    public double getRotDecel() {
        return driveLimits.get(Command.DriveLimit.ROT_DECEL, getParameters());
    }

    private void setDriveLimit(Command.DriveLimit limit, double value) {
        Command.SetDriveLimit c = driveLimits.set(limit, value, getName(), maxima.get(switch (limit) {
            case TRANS_ACCEL -> Maxima.Absolute.TRANS_ACCEL;
            case TRANS_DECEL -> Maxima.Absolute.TRANS_DECEL;
            case ROT_ACCEL -> Maxima.Absolute.ROT_ACCEL;
            case ROT_DECEL -> Maxima.Absolute.ROT_DECEL;
        }));
        if (c != null) {
            request(c);
        }
    }

    /** @return the rotational limit, deg/s */
    public double getMaxRotVel() {
        return maxRotVel;
    }

    // ---- absolute maxima, the negative and lateral limits ----

    /** @return the absolute maximum translational velocity, mm/s: the parameter file's {@code MaxVelocity} until set */
    public double getAbsoluteMaxTransVel() {
        return maxima.get(Maxima.Absolute.TRANS_VEL);
    }

    /**
     * Sets the absolute maximum translational velocity, as ARIA's {@code ArRobot::setAbsoluteMaxTransVel} (ArRobot.cpp)
     * (ArRobot.cpp): 0 or less is refused with a log line; over the top (the parameter file's
     * {@code MaxVelocity}, what the Environment drives) is capped with a log line; a velocity limit
     * above the new maximum comes down to it.
     *
     * @param maxVel mm/s
     * @return false if refused
     */
    public boolean setAbsoluteMaxTransVel(double maxVel) {
        Double v = maxima.set(Maxima.Absolute.TRANS_VEL, maxVel, getName());
        if (v != null && getTransVelMax() > v) {
            setTransVelMax(v);
        }
        return v != null;
    }

    /** @return the absolute maximum backwards velocity, mm/s, negative: −{@code MaxVelocity} until set */
    public double getAbsoluteMaxTransNegVel() {
        return maxima.get(Maxima.Absolute.TRANS_NEG_VEL);
    }

    /**
     * As {@link #setAbsoluteMaxTransVel} for backwards (ARIA's {@code ArRobot::setAbsoluteMaxTransNegVel}
     * (ArRobot.cpp)): 0 or more is refused, below −{@code MaxVelocity} capped, each with a log line; a
     * {@link #getTransNegVelMax()} below the new maximum comes up to it.
     *
     * @param maxNegVel mm/s, negative
     * @return false if refused
     */
    public boolean setAbsoluteMaxTransNegVel(double maxNegVel) {
        return maxima.set(Maxima.Absolute.TRANS_NEG_VEL, maxNegVel, getName()) != null;
    }

    /** @return the absolute maximum translational acceleration, mm/s² (the Environment's largest until set) */
    public double getAbsoluteMaxTransAccel() {
        return maxima.get(Maxima.Absolute.TRANS_ACCEL);
    }

    /**
     * ARIA's {@code ArRobot::setAbsoluteMaxTransAccel} (ArRobot.cpp): 0 or less refused, over the Environment's largest
     * capped, each with a log line; an acceleration above it comes down to it.
     *
     * @param maxAccel mm/s²
     * @return false if refused
     */
    public boolean setAbsoluteMaxTransAccel(double maxAccel) {
        return setAbsolute(Maxima.Absolute.TRANS_ACCEL, maxAccel, Command.DriveLimit.TRANS_ACCEL);
    }

    /** @return the absolute maximum translational deceleration, mm/s² */
    public double getAbsoluteMaxTransDecel() {
        return maxima.get(Maxima.Absolute.TRANS_DECEL);
    }

    /** @param maxDecel mm/s², as {@link #setAbsoluteMaxTransAccel} @return false if refused */
    public boolean setAbsoluteMaxTransDecel(double maxDecel) {
        return setAbsolute(Maxima.Absolute.TRANS_DECEL, maxDecel, Command.DriveLimit.TRANS_DECEL);
    }

    /** @return the absolute maximum rotational velocity, deg/s: the parameter file's {@code MaxRVelocity} until set */
    public double getAbsoluteMaxRotVel() {
        return maxima.get(Maxima.Absolute.ROT_VEL);
    }

    /**
     * ARIA's {@code ArRobot::setAbsoluteMaxRotVel} (ArRobot.cpp): 0 or less refused, over {@code
     * MaxRVelocity} capped, each with a log line; a rotational limit above it comes down to it.
     *
     * @param maxVel deg/s
     * @return false if refused
     */
    public boolean setAbsoluteMaxRotVel(double maxVel) {
        Double v = maxima.set(Maxima.Absolute.ROT_VEL, maxVel, getName());
        if (v != null && getRotVelMax() > v) {
            setRotVelMax(v);
        }
        return v != null;
    }

    /** @return the absolute maximum rotational acceleration, deg/s² */
    public double getAbsoluteMaxRotAccel() {
        return maxima.get(Maxima.Absolute.ROT_ACCEL);
    }

    /** @param maxAccel deg/s², as {@link #setAbsoluteMaxTransAccel} @return false if refused */
    public boolean setAbsoluteMaxRotAccel(double maxAccel) {
        return setAbsolute(Maxima.Absolute.ROT_ACCEL, maxAccel, Command.DriveLimit.ROT_ACCEL);
    }

    /** @return the absolute maximum rotational deceleration, deg/s² */
    public double getAbsoluteMaxRotDecel() {
        return maxima.get(Maxima.Absolute.ROT_DECEL);
    }

    /** @param maxDecel deg/s², as {@link #setAbsoluteMaxTransAccel} @return false if refused */
    public boolean setAbsoluteMaxRotDecel(double maxDecel) {
        return setAbsolute(Maxima.Absolute.ROT_DECEL, maxDecel, Command.DriveLimit.ROT_DECEL);
    }

    private boolean setAbsolute(Maxima.Absolute which, double value, Command.DriveLimit limit) {
        Double v = maxima.set(which, value, getName());
        if (v != null && driveLimits.get(limit, getParameters()) > v) {
            setDriveLimit(limit, v);
        }
        return v != null;
    }

    /**
     * @return 0: the absolute maximum lateral velocity of a robot without lateral motion (a Pioneer's
     *     config packet's)
     */
    public double getAbsoluteMaxLatVel() {
        return maxima.get(Maxima.Absolute.LAT_VEL);
    }

    /**
     * ARIA's {@code ArRobot::setAbsoluteMaxLatVel} (ArRobot.cpp): 0 or less refused with a log line;
     * anything else capped to the top, 0 for a robot without lateral motion, with a log line.
     *
     * @param maxVel mm/s
     * @return false if refused
     */
    public boolean setAbsoluteMaxLatVel(double maxVel) {
        return maxima.set(Maxima.Absolute.LAT_VEL, maxVel, getName()) != null;
    }

    /** @return 0: the absolute maximum lateral acceleration of a robot without lateral motion */
    public double getAbsoluteMaxLatAccel() {
        return maxima.get(Maxima.Absolute.LAT_ACCEL);
    }

    /** @param maxAccel mm/s², as {@link #setAbsoluteMaxLatVel} @return false if refused */
    public boolean setAbsoluteMaxLatAccel(double maxAccel) {
        return maxima.set(Maxima.Absolute.LAT_ACCEL, maxAccel, getName()) != null;
    }

    /** @return 0: the absolute maximum lateral deceleration of a robot without lateral motion */
    public double getAbsoluteMaxLatDecel() {
        return maxima.get(Maxima.Absolute.LAT_DECEL);
    }

    /** @param maxDecel mm/s², as {@link #setAbsoluteMaxLatVel} @return false if refused */
    public boolean setAbsoluteMaxLatDecel(double maxDecel) {
        return maxima.set(Maxima.Absolute.LAT_DECEL, maxDecel, getName()) != null;
    }

    /** @return the backwards velocity limit, mm/s, negative: −{@code MaxVelocity} until set */
    public double getTransNegVelMax() {
        return maxima.transNegVelMax();
    }

    /**
     * ARIA's {@code ArRobot::setTransNegVelMax} (ArRobot.cpp): 0 or more is ignored, below {@link
     * #getAbsoluteMaxTransNegVel()} is capped, each with ARIA's log line. {@link #setVel} clamps backwards
     * velocities to it.
     *
     * @param negVel mm/s, negative
     */
    public void setTransNegVelMax(double negVel) {
        maxima.setTransNegVelMax(negVel, getName());
    }

    /** @return false: RoboSim's robots (Pioneers, as the parameter files give them) have no lateral motion */
    public boolean hasLatVel() {
        return false;
    }

    /** @return 0: the lateral velocity of a robot without lateral motion */
    public double getLatVel() {
        return 0;
    }

    /**
     * ARIA's {@code ArRobot::setLatVel} (ArRobot.cpp): a robot without lateral motion ({@link
     * #hasLatVel()} false) is sent nothing, as ARIA's state reflection sends no lateral command to it.
     *
     * @param latVelocity mm/s
     */
    public void setLatVel(double latVelocity) {
        LOG.fine(() -> "robot " + getName() + ": setLatVel(" + latVelocity + "): the robot has no lateral motion");
    }

    /** @return the lateral velocity limit: 0 for a robot without lateral motion */
    public double getLatVelMax() {
        return maxima.latVelMax();
    }

    /** @param vel mm/s: 0 or less ignored, over the absolute maximum (0) capped, logged at ARIA's verbose level */
    public void setLatVelMax(double vel) {
        maxima.setLateral(Maxima.Absolute.LAT_VEL, vel, getName());
    }

    /** @return the lateral acceleration: 0 for a robot without lateral motion */
    public double getLatAccel() {
        return maxima.latAccel();
    }

    /** @param acc mm/s², as {@link #setLatVelMax} */
    public void setLatAccel(double acc) {
        maxima.setLateral(Maxima.Absolute.LAT_ACCEL, acc, getName());
    }

    /** @return the lateral deceleration: 0 for a robot without lateral motion */
    public double getLatDecel() {
        return maxima.latDecel();
    }

    /** @param decel mm/s², as {@link #setLatVelMax} */
    public void setLatDecel(double decel) {
        maxima.setLateral(Maxima.Absolute.LAT_DECEL, decel, getName());
    }

    /** @return true: the velocity limits are sent to the Environment, as a Pioneer's are ({@code SettableVelMaxes}) */
    public boolean hasSettableVelMaxes() {
        return true;
    }

    /** @return true: the accelerations are sent to the Environment, as a Pioneer's are ({@code SettableAccsDecs}) */
    public boolean hasSettableAccsDecs() {
        return true;
    }

    /** @return whether the last move is done, within {@link #getMoveDoneDist()} mm */
    public boolean isMoveDone() {
        return isMoveDone(0);
    }

    /**
     * @param delta how close counts as done, mm; 0 (below 0.001 either way, as in ARIA) means
     *              {@link #getMoveDoneDist()}
     * @return true if no move is active, else whether the robot is at least |distance| − delta from
     *         where the move started
     */
    public boolean isMoveDone(double delta) {
        ArPose start = moveStart;
        if (start == null) {
            return true;
        }
        double d = Math.abs(delta) < 0.001 ? moveDoneDist : delta;
        return start.findDistanceTo(getPose()) >= Math.abs(moveDistance) - d;
    }

    /** @return whether the heading is reached, within {@link #getHeadingDoneDiff()}° */
    public boolean isHeadingDone() {
        return isHeadingDone(0);
    }

    /**
     * @param delta how close counts as done, degrees; 0 (below 0.001 either way, as in ARIA) means
     *              {@link #getHeadingDoneDiff()}
     * @return true if no heading command is active, else whether |heading − target| ≤ delta
     */
    public boolean isHeadingDone(double delta) {
        Double target = headingTarget;
        if (target == null) {
            return true;
        }
        double d = Math.abs(delta) < 0.001 ? headingDoneDiff : delta;
        return Math.abs(ArMath.subAngle(getTh(), target)) <= d;
    }

    /** @param dist how close to a move's distance {@link #isMoveDone()} counts as done, mm (ARIA's default 40) */
    public void setMoveDoneDist(double dist) {
        moveDoneDist = dist;
    }

    /** @return how close to a move's distance {@link #isMoveDone()} counts as done, mm */
    public double getMoveDoneDist() {
        return moveDoneDist;
    }

    /** @param degrees how close to a heading {@link #isHeadingDone()} counts as done (ARIA's default 3) */
    public void setHeadingDoneDiff(double degrees) {
        headingDoneDiff = degrees;
    }

    /** @return how close to a heading {@link #isHeadingDone()} counts as done, degrees */
    public double getHeadingDoneDiff() {
        return headingDoneDiff;
    }

    // ---- the pose's frame, range-device queries, stall and bumpers, battery, stopRunning ----

    /**
     * @return ARIA's pose interpolation functor: {@link #getPoseInterpPosition} as a function of the
     *         time and the pose to set, answering its code
     */
    public java.util.function.BiFunction<ArTime, ArPose, Integer> getPoseInterpPositionCallback() {
        return this::getPoseInterpPosition;
    }

    /** @return {@link #getEncoderPoseInterpPosition} as a function, as {@link #getPoseInterpPositionCallback()} */
    public java.util.function.BiFunction<ArTime, ArPose, Integer> getEncoderPoseInterpPositionCallback() {
        return this::getEncoderPoseInterpPosition;
    }

    // ---- flags, IO, charge and temperature, as far as the simulation has them ----

    /** A robot's charge state, with ARIA's codes. */
    public enum ChargeState {
        /** Not known: ARIA's answer for a robot that does not report it. */
        CHARGING_UNKNOWN(255, "Unknown"),
        /** Not charging. */
        CHARGING_NOT(0, "Not"),
        /** Bulk charge. */
        CHARGING_BULK(1, "Bulk"),
        /** Overcharge. */
        CHARGING_OVERCHARGE(2, "Overcharge"),
        /** Float charge. */
        CHARGING_FLOAT(3, "Float"),
        /** Balancing. */
        CHARGING_BALANCE(4, "Balance");

        private final int code;
        final String label;

        ChargeState(int code, String label) {
            this.code = code;
            this.label = label;
        }

        /** @return ARIA's number for the state */
        public int code() {
            return code;
        }
    }

    // ---- sonar ----

    /** @return the sonar boards by number, in number order (a copy) */
    public Map<Integer, ArRangeDevice> getSonarMap() {
        synchronized (sonarBoards) {
            return Collections.unmodifiableMap(new TreeMap<>(sonarBoards));
        }
    }

    /** The velocity limits and absolute maxima the parameters give, after the layers below have taken theirs. */
    @Override
    void useParameters(RobotParameters parameters) {
        super.useParameters(parameters);
        this.maxTransVel = parameters.maxVelocity();
        this.maxRotVel = parameters.maxRVelocity();
        maxima.reset(parameters);
    }
}
