package robosim.aria;

import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Supplier;
import robosim.hw.AbstractRobot;
import robosim.hw.HardwareOptions;
import robosim.hw.RobotRuntime;
import robosim.hw.RuntimeChoices;
import robosim.params.BumperParameters;
import robosim.params.RobotParameterFiles;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.BatteryReading;
import robosim.protocol.Command;
import robosim.protocol.RobotKind;
import robosim.protocol.RobotState;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarReading;

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
public class ArRobot extends AbstractRobot {
    /** ARIA's default for {@link #isMoveDone(double)}, mm. */
    public static final double DEFAULT_MOVE_DONE = 40;
    /** ARIA's default for {@link #isHeadingDone(double)}, degrees. */
    public static final double DEFAULT_HEADING_DONE = 3;
    /** ARIA's {@code isStopped} translational threshold, mm/s. */
    public static final double STOPPED_VEL = 4;
    /** ARIA's {@code isStopped} rotational threshold, deg/s. */
    public static final double STOPPED_ROT_VEL = 1;

    private volatile SonarRing sonar;
    private final ReentrantLock lock = new ReentrantLock();
    private final TaskList sensorInterpTasks = new TaskList("sensor interpretation");
    private final TaskList userTasks = new TaskList("user");
    private final RangeDevices rangeDevices = new RangeDevices();
    private volatile ArKeyHandler keyHandler;
    private volatile ArDeviceConnection deviceConnection;
    /** Runtimes made for Pioneer robot servers, for their names. */
    private static final AtomicInteger PIONEER_RUNTIMES = new AtomicInteger();
    private final java.util.concurrent.ConcurrentSkipListMap<Integer, ArLaser> lasers =
            new java.util.concurrent.ConcurrentSkipListMap<>();
    private volatile long counter;
    private volatile boolean sonarEnabled = true;
    private volatile boolean runningAsync;
    private volatile ArPose moveStart;
    private volatile double moveDistance;
    private volatile Double headingTarget;
    private volatile double maxTransVel;
    private final DriveLimits driveLimits = new DriveLimits();
    private final Odometer odometer = new Odometer();
    /** The battery's readings and their averages. */
    private final BatteryGauge battery = new BatteryGauge();
    private volatile double moveDoneDist = DEFAULT_MOVE_DONE;
    private volatile double headingDoneDiff = DEFAULT_HEADING_DONE;
    private volatile double stoppedVel = STOPPED_VEL;
    private volatile double stoppedRotVel = STOPPED_ROT_VEL;
    private volatile double maxRotVel;
    private final ActionDriver actions = new ActionDriver(this);
    private volatile ArTransform encoderTransform = new ArTransform();
    private volatile BumperParameters bumpers = BumperParameters.ARIA_DEFAULTS;
    private volatile boolean cycleStopped;
    private volatile int sonarCycleMs;

    /** Robots made without a name, for ARIA's default names: robot, robot2, robot3, ... */
    private static final AtomicInteger UNNAMED = new AtomicInteger();

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

    private static String defaultName() {
        int n = UNNAMED.incrementAndGet();
        return n == 1 ? "robot" : "robot" + n;
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
    }

    /**
     * @param name       the robot's name in the world
     * @param host       the Environment's host
     * @param port       the Environment's robot port
     * @param parameters the robot's parameters; the robot has no bump rings (ARIA's default), as
     *                   these are read from a parameter file's bumper keys
     */
    public ArRobot(String name, String host, int port, RobotParameters parameters) {
        super(name, host, port, RobotKind.PIONEER.id(), parameters);
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

    /** The limits and sonar ring the parameters give. */
    private void useParameters(RobotParameters parameters) {
        this.maxTransVel = parameters.maxVelocity();
        this.maxRotVel = parameters.maxRVelocity();
        this.sonar = new SonarRing(parameters.sonarUnits(), parameters.sonarMaxRange());
    }


    /**
     * Connects to the Environment, waiting (bounded) for its welcome.
     *
     * @return true if connected; otherwise {@link #getConnectionError()} says why
     */
    public boolean blockingConnect() {
        ArDeviceConnection through = deviceConnection;
        if (through != null && !isConnected()) {
            usePioneerServer(getName(), through.host(), through.port());
        }
        return tryConnect(HardwareOptions.defaults());
    }

    /**
     * Gives the robot the connection it connects through, as an ARIA program that opens its own
     * does: {@link #blockingConnect()} then drives the Pioneer robot server at its address.
     *
     * @param connection the connection, or null to connect to the robot's Environment as made
     */
    public void setDeviceConnection(ArDeviceConnection connection) {
        deviceConnection = connection;
    }

    /** @return the connection given, or null */
    public ArDeviceConnection getDeviceConnection() {
        return deviceConnection;
    }

    /** Sends the robot to the Pioneer robot server at an address when it connects: a runtime of its own names it. */
    void usePioneerServer(String name, String host, int port) {
        setRuntime(RobotRuntime.create("pioneer-" + PIONEER_RUNTIMES.incrementAndGet(),
                RuntimeChoices.fromSystemProperties().withPioneer(host + ":" + port)));
        relocate(name, host, port, getParameters());
    }

    /**
     * The original RoboSim's name for {@link #blockingConnect()}.
     *
     * @return whether the robot connected
     */
    public boolean blocking_connect() {
        return blockingConnect();
    }

    /**
     * One robot cycle, run as each step's state arrives (while the robot's code is yielded): the
     * counter goes up, the sonar readings are taken, then the sensor-interpretation tasks, the
     * actions (resolved and sent, see {@link #addAction}) and the user tasks run, in ARIA's task
     * order, all under the robot's lock, as ARIA's cycle does.
     */
    @Override
    protected void responded(RobotSensorResponse response) {
        lock.lock();
        try {
            super.responded(response);
            if (cycleStopped) {
                return;
            }
            counter++;
            RobotState s = response.state();
            SonarReading ring = s.get(SonarReading.PART);
            sonar.update(ring.ranges(), ring.fresh(), getPose(), counter, s.timeMs());
            odometer.update(s);
            battery.update(s.get(BatteryReading.PART));
            sensorInterpTasks.runAll(getName());
            actions.cycle(s.timeMs());
            userTasks.runAll(getName());
        } finally {
            lock.unlock();
        }
    }

    // ---- the cycle, tasks and the robot's lock ----

    /** @return the cycle counter: one more for every step's state received */
    public long getCounter() {
        return counter;
    }

    /**
     * Adds a task run once per cycle after the sensor-interpretation tasks, in step with the
     * simulation: a program written as tasks is deterministic by construction. A task must not
     * sleep; its motion calls are sent with the cycle's requests.
     *
     * @param name     the task's name (adding a name again replaces that task)
     * @param position higher positions run first
     * @param task     the task
     */
    public void addUserTask(String name, int position, Runnable task) {
        userTasks.add(name, position, task);
    }

    /** @param name the user task to remove @return whether it was there */
    public boolean remUserTask(String name) {
        return userTasks.remove(name);
    }

    /**
     * Adds a task run once per cycle right after the new readings are in, before the user tasks:
     * where range devices take their readings.
     *
     * @param name     the task's name
     * @param position higher positions run first
     * @param task     the task
     */
    public void addSensorInterpTask(String name, int position, Runnable task) {
        sensorInterpTasks.add(name, position, task);
    }

    /** @param name the sensor-interpretation task to remove @return whether it was there */
    public boolean remSensorInterpTask(String name) {
        return sensorInterpTasks.remove(name);
    }

    /** Takes the robot's lock, which the cycle holds while it updates the robot and runs its tasks. */
    public void lock() {
        lock.lock();
    }

    /** @return whether the lock was free and is now held */
    public boolean tryLock() {
        return lock.tryLock();
    }

    /** Releases the robot's lock. */
    public void unlock() {
        lock.unlock();
    }

    /**
     * Yields in simulated time (see {@link ArUtil#sleep}).
     *
     * @param ms simulated milliseconds
     * @throws IllegalStateException if the calling thread holds the robot's lock, which the cycle
     *                               needs to deliver the next step
     */
    @Override
    public void sleepSimulated(long ms) {
        if (lock.isHeldByCurrentThread()) {
            throw new IllegalStateException("robot " + getName() + ": sleeping while holding the robot's lock"
                    + " would stop its cycle; unlock() first");
        }
        super.sleepSimulated(ms);
    }

    /** @return whether the calling thread holds the robot's lock */
    boolean isLockedByMe() {
        return lock.isHeldByCurrentThread();
    }

    /**
     * Lets the robot's cycle (its tasks) go on when the program's threads end: the robot then stays
     * in the run until the Environment ends it or {@link #disconnect()} is called. The cycle itself
     * always runs, on the robot's hardware thread.
     */
    public void runAsync() {
        cycleStopped = false;
        runningAsync = true;
        if (isConnected()) {
            keepAlive(true);
        }
    }

    /**
     * ARIA's {@code runAsync(stopRunIfNotConnected)}: as {@link #runAsync()}. The cycle always stops
     * when the robot is disconnected, so the flag changes nothing here.
     *
     * @param stopRunIfNotConnected ARIA's: whether the cycle stops without a connection
     */
    public void runAsync(boolean stopRunIfNotConnected) {
        runAsync();
    }

    /** @return whether {@link #runAsync()} was called and the robot is still connected */
    public boolean isRunning() {
        return runningAsync && isConnected();
    }

    /** Runs the robot's cycle until the robot is disconnected: the calling thread yields meanwhile. */
    public void run() {
        runAsync();
        waitForRunExit();
    }

    /**
     * ARIA's {@code run(stopRunIfNotConnected)}: as {@link #run()}; the cycle always stops when the
     * robot is disconnected.
     *
     * @param stopRunIfNotConnected ARIA's: whether the cycle stops without a connection
     */
    public void run(boolean stopRunIfNotConnected) {
        run();
    }

    /** Waits, yielded, until the robot is disconnected. */
    public void waitForRunExit() {
        while (isConnected()) {
            sleepSimulated(Long.MAX_VALUE / 4);
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
     * @param heading a heading in the robot's frame (the one {@link #moveTo} set), degrees
     * @return the same heading in the encoder frame, in which the Environment turns
     */
    double encoderHeading(double heading) {
        double frameTh = encoderTransform.getTh();
        return frameTh == 0 ? heading : ArMath.subAngle(heading, frameTh);
    }

    private long simulatedMs() {
        return state().timeMs();
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
        addSensorInterpTask("Key Handler", 50, handler::checkKeys);
        if (exitOnEscape) {
            handler.addKeyHandler(ArKeyHandler.ESCAPE, () -> {
                ArLog.log(ArLog.Terse, "Escape was pressed, program is exiting.");
                if (useExitNotShutdown) {
                    Aria.exit(0);
                } else {
                    stopRunning();
                    Aria.shutdown();
                }
            });
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
        request(move);
        actions.directTrans(simulatedMs());
    }

    /** Translational and rotational velocity to zero at once. */
    public void stop() {
        moveStart = null;
        headingTarget = null;
        request(new Command.Stop());
        actions.stopped(simulatedMs());
    }

    /**
     * @param velocity mm/s, rounded and clamped to the maximum translational velocity
     * @throws IllegalArgumentException if it is not finite
     */
    public void setVel(double velocity) {
        Command.SetVel vel = new Command.SetVel(Math.rint(velocity));
        moveStart = null;
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
        Command.SetMaxTransVel limit = new Command.SetMaxTransVel(velocity);
        maxTransVel = Math.max(0, Math.min(velocity, getParameters().maxVelocity()));
        request(limit);
    }

    /**
     * @param velocity new rotational limit, deg/s, within the parameter file's maximum
     * @throws IllegalArgumentException if it is not finite
     */
    public void setMaxRotVel(double velocity) {
        Command.SetMaxRotVel limit = new Command.SetMaxRotVel(velocity);
        maxRotVel = Math.max(0, Math.min(velocity, getParameters().maxRVelocity()));
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
     * @param vel the new limit, mm/s; capped at the parameter file's {@code MaxVelocity}
     */
    public void setTransVelMax(double vel) {
        if (!DriveLimits.ignoresVelocity("setTransVelMax", vel, getName())) {
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
     * @param vel the new limit, deg/s; capped at the parameter file's {@code MaxRVelocity}
     */
    public void setRotVelMax(double vel) {
        if (!DriveLimits.ignoresVelocity("setRotVelMax", vel, getName())) {
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
        Command.SetDriveLimit c = driveLimits.set(limit, value, getName());
        if (c != null) {
            request(c);
        }
    }

    /** @return the rotational limit, deg/s */
    public double getMaxRotVel() {
        return maxRotVel;
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

    // ---- state ----

    /** @return odometry x, mm (in the frame {@link #moveTo} set, if it was called) */
    public double getX() {
        return getPose().getX();
    }

    /** @return odometry y, mm (in the frame {@link #moveTo} set, if it was called) */
    public double getY() {
        return getPose().getY();
    }

    /** @return odometry heading, degrees in (-180, 180] (in the frame {@link #moveTo} set) */
    public double getTh() {
        return getPose().getTh();
    }

    /**
     * @return the odometry pose, a new object: the encoder pose ({@link #getEncoderPose()}) carried
     *         into the frame {@link #moveTo} set, as ARIA's encoder transform carries it
     */
    public ArPose getPose() {
        return encoderTransform.doTransform(getEncoderPose());
    }

    /** @return translational velocity, (left + right) / 2, mm/s */
    public double getVel() {
        return state().vel();
    }

    /** @return rotational velocity, deg/s */
    public double getRotVel() {
        return state().rotVel();
    }

    /** @return left wheel velocity, mm/s */
    public double getLeftVel() {
        return state().leftVel();
    }

    /** @return right wheel velocity, mm/s */
    public double getRightVel() {
        return state().rightVel();
    }

    /** @return whether a collision stopped the robot's last motion */
    public boolean isStalled() {
        return state().stalled();
    }

    /**
     * @return the distance travelled since the program connected, mm: ARIA's virtual odometer, the
     *         sum over the cycles of the straight line between one odometry pose and the next
     */
    public double getOdometerDistance() {
        return odometer.distance();
    }

    /** @return the degrees turned since the program connected: the sum of each cycle's absolute heading change */
    public double getOdometerDegrees() {
        return odometer.degrees();
    }

    /** @return the simulated seconds since the program connected, whole */
    public long getOdometerTime() {
        return odometer.seconds();
    }

    /** @return the distance travelled since {@link #resetTripOdometer()} (or since connecting), mm */
    public double getTripOdometerDistance() {
        return odometer.tripDistance();
    }

    /** @return the degrees turned since {@link #resetTripOdometer()} (or since connecting) */
    public double getTripOdometerDegrees() {
        return odometer.tripDegrees();
    }

    /** @return the simulated seconds since {@link #resetTripOdometer()} (or since connecting), whole */
    public long getTripOdometerTime() {
        return odometer.tripSeconds();
    }

    /** Starts the trip odometer again: its distance, degrees and time count from now. */
    public void resetTripOdometer() {
        odometer.resetTrip();
    }

    /**
     * @return whether the robot is stopped: at most the stopped velocities ({@link #setStoppedVels},
     *         ARIA's 4 mm/s and 1 deg/s by default)
     */
    public boolean isStopped() {
        return isStopped(0, 0);
    }

    /**
     * @param vel    the translational speed that counts as stopped, mm/s; below 0.001 means the
     *               robot's own ({@link #setStoppedVels}), as in ARIA
     * @param rotVel the rotational speed that counts as stopped, deg/s; below 0.001 likewise
     * @return whether |velocity| and |rotational velocity| are at most these
     */
    public boolean isStopped(double vel, double rotVel) {
        double v = vel < 0.001 ? stoppedVel : vel;
        double r = rotVel < 0.001 ? stoppedRotVel : rotVel;
        return Math.abs(getVel()) <= v && Math.abs(getRotVel()) <= r;
    }

    /**
     * @param vel    the translational speed {@link #isStopped()} counts as stopped, mm/s
     * @param rotVel the rotational speed it counts as stopped, deg/s
     */
    public void setStoppedVels(double vel, double rotVel) {
        stoppedVel = vel;
        stoppedRotVel = rotVel;
    }

    /** @return the radius of the circle enclosing the robot, mm */
    public double getRobotRadius() {
        return getParameters().robotRadius();
    }

    /** @return the robot's width, mm */
    public double getRobotWidth() {
        return getParameters().robotWidth();
    }

    /** @return the robot's length, mm */
    public double getRobotLength() {
        return getParameters().robotLength();
    }

    /** @return the robot's length ahead of its centre, mm */
    public double getRobotLengthFront() {
        return getParameters().robotLengthFront();
    }

    /** @return the robot's length behind its centre, mm */
    public double getRobotLengthRear() {
        return getParameters().robotLengthRear();
    }

    /**
     * @return whether the left motor is stalled: bit 0 of {@link #getStallValue()}, as ARIA's
     *         {@code ArRobot.h} reads it (RoboSim stalls both wheels together)
     */
    public boolean isLeftMotorStalled() {
        return (getStallValue() & StallValue.LEFT_MOTOR) != 0;
    }

    /**
     * @return whether the right motor is stalled: bit 8 of {@link #getStallValue()}, as ARIA's
     *         {@code ArRobot.h} reads it
     */
    public boolean isRightMotorStalled() {
        return (getStallValue() & StallValue.RIGHT_MOTOR) != 0;
    }

    // ---- the pose's frame, range-device queries, stall and bumpers, battery, stopRunning ----

    /**
     * @return the pose the robot's encoders give (the Environment's odometry), which
     *         {@link #moveTo} does not change; a new object
     */
    public ArPose getEncoderPose() {
        RobotState s = state();
        return new ArPose(s.x(), s.y(), s.th());
    }

    /** @return the transform from the encoder pose to {@link #getPose()} (the identity until {@link #moveTo}) */
    public ArTransform getEncoderTransform() {
        return encoderTransform;
    }

    /**
     * Re-bases the odometric pose, moving the readings of the range devices with the robot, as ARIA's
     * {@code ArRobot::moveTo(pose)} (with {@code doCumulative} true) does. The robot does not drive:
     * from now on {@link #getPose()} answers {@code pose} plus whatever the encoders add, while
     * {@link #getEncoderPose()} keeps the raw pose. Headings given to {@link #setHeading} are in the
     * new frame.
     *
     * @param pose the robot's new pose, mm and degrees
     */
    public void moveTo(ArPose pose) {
        moveTo(pose, true);
    }

    /**
     * As {@link #moveTo(ArPose)}.
     *
     * @param pose         the robot's new pose
     * @param doCumulative whether the range devices' cumulative buffers move too (the current
     *                     buffers and the sonar readings always do)
     */
    public void moveTo(ArPose pose, boolean doCumulative) {
        rebase(new ArTransform(getEncoderPose(), pose), doCumulative);
    }

    /**
     * ARIA's {@code moveTo(poseTo, poseFrom)}: the robot is taken to have been at {@code from} (a pose
     * in the current frame) and to be at {@code to} there; the frame moves by that difference.
     *
     * @param to   where {@code from} is in the new frame
     * @param from a pose in the current frame
     */
    public void moveTo(ArPose to, ArPose from) {
        moveTo(to, from, true);
    }

    /**
     * As {@link #moveTo(ArPose, ArPose)}.
     *
     * @param to           where {@code from} is in the new frame
     * @param from         a pose in the current frame
     * @param doCumulative whether the range devices' cumulative buffers move too
     */
    public void moveTo(ArPose to, ArPose from, boolean doCumulative) {
        rebase(new ArTransform(encoderTransform.doInvTransform(from), to), doCumulative);
    }

    private void rebase(ArTransform newEncoderTransform, boolean doCumulative) {
        lock.lock();
        try {
            ArPose before = getPose();
            encoderTransform = newEncoderTransform;
            ArTransform moved = new ArTransform(before, getPose());
            rangeDevices.applyTransform(moved, doCumulative);
            sonar.applyTransform(moved);
        } finally {
            lock.unlock();
        }
    }

    /**
     * The nearest current reading of all the attached range devices in an angle interval (ARIA's
     * {@code checkRangeDevicesCurrentPolar}).
     *
     * @param startAngle degrees, relative to the robot's heading
     * @param endAngle   degrees, relative to the robot's heading
     * @return the smallest {@link ArRangeDevice#currentReadingPolar} over the devices (a device with
     *         nothing there answers its maximum range); −1 if no device is attached
     */
    public double checkRangeDevicesCurrentPolar(double startAngle, double endAngle) {
        return checkRangeDevicesCurrentPolar(startAngle, endAngle, null);
    }

    /**
     * As {@link #checkRangeDevicesCurrentPolar(double, double)}, also giving the reading's angle.
     *
     * @param startAngle degrees, relative to the robot's heading
     * @param endAngle   degrees, relative to the robot's heading
     * @param angleOut   null, or an array whose element 0 receives the nearest reading's angle
     * @return the distance, mm, or −1 if no device is attached
     */
    public double checkRangeDevicesCurrentPolar(double startAngle, double endAngle, double[] angleOut) {
        return rangeDevices.nearest(d -> d.currentReadingPolar(startAngle, endAngle, null),
                (d, out) -> d.currentReadingPolar(startAngle, endAngle, out), angleOut);
    }

    /**
     * The nearest cumulative reading of all the attached range devices in an angle interval (ARIA's
     * {@code checkRangeDevicesCumulativePolar}).
     *
     * @param startAngle degrees, relative to the robot's heading
     * @param endAngle   degrees, relative to the robot's heading
     * @return the smallest {@link ArRangeDevice#cumulativeReadingPolar} over the devices; −1 if no
     *         device is attached
     */
    public double checkRangeDevicesCumulativePolar(double startAngle, double endAngle) {
        return checkRangeDevicesCumulativePolar(startAngle, endAngle, null);
    }

    /**
     * As {@link #checkRangeDevicesCumulativePolar(double, double)}, also giving the reading's angle.
     *
     * @param startAngle degrees, relative to the robot's heading
     * @param endAngle   degrees, relative to the robot's heading
     * @param angleOut   null, or an array whose element 0 receives the nearest reading's angle
     * @return the distance, mm, or −1 if no device is attached
     */
    public double checkRangeDevicesCumulativePolar(double startAngle, double endAngle, double[] angleOut) {
        return rangeDevices.nearest(d -> d.cumulativeReadingPolar(startAngle, endAngle, null),
                (d, out) -> d.cumulativeReadingPolar(startAngle, endAngle, out), angleOut);
    }

    /**
     * The nearest current reading of all the attached range devices in a box around the robot
     * (ARIA's {@code checkRangeDevicesCurrentBox}).
     *
     * @param x1 one corner's x, mm, robot frame (x forward)
     * @param y1 one corner's y, mm, robot frame (y left)
     * @param x2 the opposite corner's x, mm
     * @param y2 the opposite corner's y, mm
     * @return the smallest {@link ArRangeDevice#currentReadingBox} over the devices; −1 if no
     *         device is attached
     */
    public double checkRangeDevicesCurrentBox(double x1, double y1, double x2, double y2) {
        return checkRangeDevicesCurrentBox(x1, y1, x2, y2, null);
    }

    /**
     * As {@link #checkRangeDevicesCurrentBox(double, double, double, double)}, also giving the reading.
     *
     * @param x1         one corner's x, mm, robot frame
     * @param y1         one corner's y, mm, robot frame
     * @param x2         the opposite corner's x, mm
     * @param y2         the opposite corner's y, mm
     * @param readingPos null, or a pose set to the nearest reading in the robot's frame ((0, 0, 0)
     *                   if the nearest device has none in the box, as in ARIA)
     * @return the distance, mm, or −1 if no device is attached
     */
    public double checkRangeDevicesCurrentBox(double x1, double y1, double x2, double y2, ArPose readingPos) {
        return rangeDevices.nearest(d -> d.currentReadingBox(x1, y1, x2, y2, null),
                (d, out) -> d.currentReadingBox(x1, y1, x2, y2, out), readingPos);
    }

    /**
     * The nearest cumulative reading of all the attached range devices in a box around the robot
     * (ARIA's {@code checkRangeDevicesCumulativeBox}).
     *
     * @param x1 one corner's x, mm, robot frame
     * @param y1 one corner's y, mm, robot frame
     * @param x2 the opposite corner's x, mm
     * @param y2 the opposite corner's y, mm
     * @return the smallest {@link ArRangeDevice#cumulativeReadingBox} over the devices; −1 if no
     *         device is attached
     */
    public double checkRangeDevicesCumulativeBox(double x1, double y1, double x2, double y2) {
        return checkRangeDevicesCumulativeBox(x1, y1, x2, y2, null);
    }

    /**
     * As {@link #checkRangeDevicesCumulativeBox(double, double, double, double)}, also giving the
     * reading.
     *
     * @param x1         one corner's x, mm, robot frame
     * @param y1         one corner's y, mm, robot frame
     * @param x2         the opposite corner's x, mm
     * @param y2         the opposite corner's y, mm
     * @param readingPos null, or a pose set to the nearest reading in the robot's frame
     * @return the distance, mm, or −1 if no device is attached
     */
    public double checkRangeDevicesCumulativeBox(double x1, double y1, double x2, double y2, ArPose readingPos) {
        return rangeDevices.nearest(d -> d.cumulativeReadingBox(x1, y1, x2, y2, null),
                (d, out) -> d.cumulativeReadingBox(x1, y1, x2, y2, out), readingPos);
    }

    /**
     * The Pioneer's stall and bumper flags, with ARIA's layout: bit 0 the left motor's stall, bits
     * 1–7 the rear bumpers, bit 8 the right motor's stall, bits 9–15 the front bumpers (bumper i in
     * bit 1 + i, or 9 + i). The bumper flags come from the body's six contact sectors (see
     * {@link ArBumpers} and docs/ARIA-SEMANTICS.md for the mapping); a ring the parameter file does
     * not declare reports none.
     *
     * @return the flags of the latest cycle
     */
    public int getStallValue() {
        return StallValue.of(state(), bumpers);
    }

    /** @return whether a front bumper is pressed (and the robot has a front ring), as in ARIA */
    public boolean isFrontBumperTriggered() {
        return hasFrontBumpers() && (getStallValue() >> 9 & 0x7f) != 0;
    }

    /** @return whether a rear bumper is pressed (and the robot has a rear ring), as in ARIA */
    public boolean isRearBumperTriggered() {
        return hasRearBumpers() && (getStallValue() >> 1 & 0x7f) != 0;
    }

    /** @return whether the parameter file gives the robot a front bump ring ({@code FrontBumpers}) */
    public boolean hasFrontBumpers() {
        return bumpers.frontBumpers();
    }

    /** @return the front ring's bumpers ({@code NumFrontBumpers}, ARIA's default 5) */
    public int getNumFrontBumpers() {
        return bumpers.numFrontBumpers();
    }

    /** @return whether the parameter file gives the robot a rear bump ring ({@code RearBumpers}) */
    public boolean hasRearBumpers() {
        return bumpers.rearBumpers();
    }

    /** @return the rear ring's bumpers ({@code NumRearBumpers}, ARIA's default 5) */
    public int getNumRearBumpers() {
        return bumpers.numRearBumpers();
    }

    /** @return what the read gives, taken under the robot's lock */
    private <T> T underLock(Supplier<T> read) {
        lock.lock();
        try {
            return read.get();
        } finally {
            lock.unlock();
        }
    }

    /** Does a change under the robot's lock. */
    private void underLock(Runnable change) {
        lock.lock();
        try {
            change.run();
        } finally {
            lock.unlock();
        }
    }

    /**
     * The battery voltage on ARIA's 12 V scale, averaged over the latest
     * {@link #getBatteryVoltageAverageOfNum()} readings (20), as ARIA averages its SIPs'. The
     * simulated battery is a Pioneer 3's 12 V pack: 13 V full, lower while the motors draw and the
     * longer they have driven (see docs/ARIA-API.md).
     *
     * @return volts
     */
    public double getBatteryVoltage() {
        return underLock(() -> battery.voltage());
    }

    /** @return the latest battery reading, volts, not averaged */
    public double getBatteryVoltageNow() {
        return underLock(() -> battery.voltageNow());
    }

    /** @return the real battery voltage, averaged: the same as {@link #getBatteryVoltage()} for a 12 V pack */
    public double getRealBatteryVoltage() {
        return underLock(() -> battery.realVoltage());
    }

    /** @return the latest real battery voltage, volts: the same as {@link #getBatteryVoltageNow()} */
    public double getRealBatteryVoltageNow() {
        return getBatteryVoltageNow();
    }

    /** @return whether the robot reports its state of charge: once a reading above 0 has come */
    public boolean haveStateOfCharge() {
        return underLock(() -> battery.haveStateOfCharge());
    }

    /** @return as {@link #haveStateOfCharge()} */
    public boolean hasStateOfCharge() {
        return haveStateOfCharge();
    }

    /** @return the charge left, percent, 0 to 100; 0 when the robot does not report it */
    public double getStateOfCharge() {
        return underLock(() -> battery.stateOfCharge());
    }

    /** @return how many readings {@link #getBatteryVoltage()} averages */
    public int getBatteryVoltageAverageOfNum() {
        return underLock(() -> battery.averageOf());
    }

    /**
     * @param numToAverage how many readings {@link #getBatteryVoltage()} averages from now on
     * @throws IllegalArgumentException if less than 1
     */
    public void setBatteryVoltageAverageOfNum(int numToAverage) {
        underLock(() -> battery.setAverageOf(numToAverage));
    }

    /** @return how many readings {@link #getRealBatteryVoltage()} averages */
    public int getRealBatteryVoltageAverageOfNum() {
        return underLock(() -> battery.realAverageOf());
    }

    /**
     * @param numToAverage how many readings {@link #getRealBatteryVoltage()} averages from now on
     * @throws IllegalArgumentException if less than 1
     */
    public void setRealBatteryVoltageAverageOfNum(int numToAverage) {
        underLock(() -> battery.setRealAverageOf(numToAverage));
    }

    /**
     * Stops the robot's cycle and disconnects, as ARIA's {@code stopRunning()}: a {@link #run()} in
     * another thread returns.
     */
    public void stopRunning() {
        stopRunning(true);
    }

    /**
     * Stops the robot's cycle (ARIA's {@code stopRunning(doDisconnect)}): from the next state on, the
     * counter stops, the sonar readings, odometers and range devices are no longer updated and no
     * task runs, until {@link #runAsync()} starts the cycle again. The pose and velocities still
     * follow the Environment's state.
     *
     * @param doDisconnect whether to leave the run too
     */
    public void stopRunning(boolean doDisconnect) {
        cycleStopped = true;
        runningAsync = false;
        if (isConnected()) {
            keepAlive(false);
        }
        if (doDisconnect) {
            disconnect();
        }
    }

    /**
     * Asks the Environment to fire the sonar ring in sequence when the parameter file gives a
     * {@code SonarCycle} (see {@link #getSonarCycle()}).
     */
    @Override
    protected void welcomed(RobotState initial) {
        if (sonarCycleMs > 0) {
            request(new Command.SetSonarCycle(sonarCycleMs));
        }
    }

    /**
     * @return the simulated ms between firings of the sonar ring, from the parameter file's
     *         {@code SonarCycle} (what ARIA reads from a Pioneer's config packet): each firing reads
     *         one transducer of each bank of eight, in index order, and only those are new in that
     *         cycle ({@link #isSonarNew}); 0 when every transducer fires every step
     */
    public int getSonarCycle() {
        return sonarCycleMs;
    }

    // ---- the motors ----

    /**
     * Enables the motors, as ARIA's {@code enableMotors} sends ENABLE 1 (ArRobot.cpp). A Pioneer's
     * motors are disabled when its program connects (unless the world says {@code motors="enabled"}):
     * until this call the velocity, move and heading commands are ignored, and the robot is told
     * once in its state's errors. {@link #areMotorsEnabled()} says so from the next cycle on.
     */
    public void enableMotors() {
        request(new Command.SetMotors(true));
    }

    /**
     * Disables the motors, as ARIA's {@code disableMotors} sends ENABLE 0: the robot stops at once
     * and ignores motion commands until {@link #enableMotors()}.
     */
    public void disableMotors() {
        request(new Command.SetMotors(false));
    }

    /**
     * Whether the motors are enabled, as the latest state says: like ARIA's, which reads the flag of
     * the latest SIP (ArRobot.h), it reflects {@link #enableMotors()} only after the next cycle.
     *
     * @return whether the robot reported its motors enabled; false before it has said
     */
    public boolean areMotorsEnabled() {
        RobotState s = state();
        return s != null && Boolean.TRUE.equals(s.motorsEnabled());
    }

    // ---- sonar ----

    /** @return the number of sonar units in the parameter file */
    public int getNumSonar() {
        return sonar.size();
    }

    /**
     * @param num the sonar's index
     * @return its range from the transducer in mm; 5000 (the maximum) if it never reported; −1 for a
     *         bad index
     */
    public int getSonarRange(int num) {
        return sonar.range(num);
    }

    /**
     * @param num the sonar's index
     * @return its reading, or null for a bad index
     */
    public ArSensorReading getSonarReading(int num) {
        return sonar.reading(num);
    }

    /**
     * @param num the sonar's index
     * @return whether its reading arrived in this cycle (ARIA: its counter equals the robot's);
     *         false for a bad index
     */
    public boolean isSonarNew(int num) {
        return sonar.isNew(num, counter);
    }

    /** Turns the sonars on (they are on after connecting). */
    public void enableSonar() {
        sonarEnabled = true;
        request(new Command.SetSonar(true));
    }

    /** Turns the sonars off: no new readings arrive until {@link #enableSonar()}. */
    public void disableSonar() {
        sonarEnabled = false;
        request(new Command.SetSonar(false));
    }

    /** @return whether the sonars are on */
    public boolean areSonarsEnabled() {
        return sonarEnabled;
    }

    /**
     * The nearest sonar range among the sonars mounted strictly inside an angle interval, by ARIA's
     * rule (see {@link ArMath#angleBetween}).
     *
     * @param startAngle degrees, robot-relative
     * @param endAngle   degrees, robot-relative
     * @return the range in mm, or −1 if no sonar is in the interval
     */
    public int getClosestSonarRange(double startAngle, double endAngle) {
        int n = getClosestSonarNumber(startAngle, endAngle);
        return n < 0 ? -1 : getSonarRange(n);
    }

    /**
     * @param startAngle degrees, robot-relative
     * @param endAngle   degrees, robot-relative
     * @return the index of the sonar with the nearest range inside the interval (ties to the lowest
     *         index), or −1 if none
     */
    public int getClosestSonarNumber(double startAngle, double endAngle) {
        return sonar.closest(startAngle, endAngle);
    }
}
