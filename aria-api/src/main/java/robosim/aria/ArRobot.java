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
 *
 * <p>Its methods are declared by topic in the package-private layers it extends, each over the one
 * before: the connection ({@code ArRobotConnection}), the cycle ({@code ArRobotCycle}), the body and
 * devices ({@code ArRobotDevices}), the pose ({@code ArRobotPose}) and the motion
 * ({@code ArRobotMotion}); they are this class's public methods all the same. This class adds the
 * constructors, the actions, the range devices, the direct commands, the key handler and the lasers.
 */
public class ArRobot extends ArRobotMotion {
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
        parametersFrom(paramFile);
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

    // ---- the states of ARIA's waits and charge ----

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

    // ---- range devices ----

    /** @param device a range device to attach; its robot becomes this one */
    public void addRangeDevice(ArRangeDevice device) {
        rangeDevices.add(device, this);
    }

    /** @param device a range device to detach; its robot is cleared */
    public void remRangeDevice(ArRangeDevice device) {
        rangeDevices.remove(device);
    }

    /** @param name the name of a range device to detach (the first of that name) */
    public void remRangeDevice(String name) {
        ArRangeDevice d = rangeDevices.find(name);
        if (d != null) {
            rangeDevices.remove(d);
        }
    }

    /** @param name a device's name @return the first attached device of that name, or null */
    public ArRangeDevice findRangeDevice(String name) {
        return rangeDevices.find(name);
    }

    /** @return the attached range devices */
    public List<ArRangeDevice> getRangeDeviceList() {
        return rangeDevices.list();
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

    // ---- generic getters: kept here, as javac's bridge to a layer's method has raw types ----

    /** @return the run-exit callbacks, in order (a copy) */
    public List<Runnable> getRunExitListCopy() {
        return events.runExit.copy();
    }

    /** @return the sonar boards by number, in number order (a copy) */
    public Map<Integer, ArRangeDevice> getSonarMap() {
        synchronized (sonarBoards) {
            return Collections.unmodifiableMap(new TreeMap<>(sonarBoards));
        }
    }

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
}
