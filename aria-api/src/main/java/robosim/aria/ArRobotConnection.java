package robosim.aria;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.logging.Logger;
import robosim.aria.ArRobot.WaitState;
import robosim.hw.AbstractRobot;
import robosim.hw.HardwareOptions;
import robosim.hw.RobotRuntime;
import robosim.hw.RunEnd;
import robosim.hw.RuntimeChoices;
import robosim.params.RobotParameterFiles;
import robosim.protocol.Command;
import robosim.protocol.RobotKind;
import robosim.protocol.RobotParameters;
import robosim.protocol.RobotState;

/**
 * {@link ArRobot}'s connection: connecting (blocking, asynchronous, through a Pioneer robot server),
 * disconnecting and dropping, who the robot is, and the connection's callbacks, times and waits, as
 * ARIA's {@code ArRobot} has them (ArRobot.cpp). The lowest of the package-private layers that
 * {@link ArRobot}, the public face, is made of, one topic each.
 */
abstract class ArRobotConnection extends AbstractRobot {
    static final Logger LOG = Logger.getLogger(ArRobot.class.getName());
    private volatile ArDeviceConnection deviceConnection;
    /** Runtimes made for Pioneer robot servers, for their names. */
    private static final AtomicInteger PIONEER_RUNTIMES = new AtomicInteger();
    /** Whether the cycle was started by {@code run} or {@code runAsync} and has not stopped. */
    volatile boolean runningAsync;
    /** The connection's callbacks, times and waits. */
    final ConnectionEvents events = new ConnectionEvents();
    /** The parameter file's {@code SonarCycle}, ms, sent when the robot is welcomed; 0 for none. */
    volatile int sonarCycleMs;
    /** Whether an ARIA connector connects the robot, which then logs ARIA's connection lines. */
    private volatile boolean ariaConnectionLines;
    /** The parameter file the robot's parameters came from, for ARIA's connection lines; null if none. */
    private volatile String parameterFile;

    /** Robots made without a name, for ARIA's default names: robot, robot2, robot3, ... */
    private static final AtomicInteger UNNAMED = new AtomicInteger();

    /** The robot, named and placed, with its parameters: see {@link ArRobot}'s constructors. */
    ArRobotConnection(String name, String host, int port, RobotParameters parameters) {
        super(name, host, port, RobotKind.PIONEER.id(), parameters);
    }

    /**
     * Restarts the trip odometer, as ARIA's {@code ArRobot::finishedConnection} (ArRobot.cpp) does once
     * the robot is connected; the pose layer keeps the odometers.
     */
    abstract void restartTripOdometer();

    // ---- connecting and disconnecting ----

    static String defaultName() {
        int n = UNNAMED.incrementAndGet();
        return n == 1 ? "robot" : "robot" + n;
    }

    /**
     * Connects to the Environment, waiting (bounded) for its welcome, then for the stabilizing time
     * ({@link #setStabilizingTime}), as ARIA's {@code ArRobot::blockingConnect} (ArRobot.cpp) does. On success the
     * stabilizing callbacks run, then the connect callbacks ({@link #addConnectCB}); on failure the
     * failed-connect callbacks ({@link #addFailedConnectCB}).
     *
     * @return true if connected; otherwise {@link #getConnectionError()} says why
     */
    public boolean blockingConnect() {
        ArDeviceConnection through = deviceConnection;
        if (through != null && !isConnected()) {
            // an ARIA program's own connection: ARIA's lines, as through a connector
            logConnectionAsAria();
            usePioneerServer(getName(), through.host(), through.port());
        }
        if (!tryConnect(HardwareOptions.defaults())) {
            failedConnect();
            return false;
        }
        while (events.isStabilizing && super.isConnected()) {
            sleepSimulated(getStepMs());
        }
        if (!isConnected()) {
            events.isStabilizing = false;
            failedConnect();
            return false;
        }
        return true;
    }

    /**
     * ARIA's {@code blockingConnect(tryHarderToConnect)}: as {@link #blockingConnect()}. Trying
     * harder (closing a connection a crashed program left open) has no meaning for the Environment.
     *
     * @param tryHarderToConnect ARIA's flag; ignored
     * @return whether the robot connected
     */
    public boolean blockingConnect(boolean tryHarderToConnect) {
        return blockingConnect();
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
     * ARIA's {@code ArRobot::asyncConnect} (ArRobot.cpp): refused (false) unless the robot's cycle was started with
     * {@link ArRobot#runAsync()} and the robot is not connected, as in ARIA. The connection itself is made
     * in the calling thread, which becomes part of the robot's code as the lockstep requires, so this
     * returns once it has succeeded or failed; as in ARIA, the callbacks and
     * {@link #waitForConnectOrConnFail} tell which.
     *
     * @return whether the connection was attempted
     */
    public boolean asyncConnect() {
        if (!runningAsync || isConnected()) {
            return false;
        }
        blockingConnect();
        return true;
    }

    /**
     * The connection failed: ARIA's {@code ArRobot::failedConnect} (ArRobot.cpp; its log line, the
     * callbacks, the waiters).
     */
    private void failedConnect() {
        LOG.warning(() -> "robot " + getName() + ": Failed to connect to robot.");
        events.failedConnect.invoke(getName());
        events.failed();
    }

    /**
     * Whether the robot is connected: as ARIA's, only once the connection has finished (the
     * Environment welcomed the robot and it has stabilized, {@link #isStabilizing()}), and until it
     * ends.
     */
    @Override
    public boolean isConnected() {
        return super.isConnected() && events.isLive();
    }

    /**
     * @return whether the robot's link to the Environment is up ({@code AbstractRobot}'s
     *     {@code isConnected}), stabilizing or not: the layers above ask this where {@link #isConnected()}
     *     would wait for the connection to finish, as ArRobot's code asked its superclass
     */
    final boolean linkConnected() {
        return super.isConnected();
    }

    /**
     * Leaves the run, as ARIA's {@code ArRobot::disconnect} (ArRobot.cpp): if the robot was connected, the
     * disconnect-normally callbacks run first ({@link #addDisconnectNormallyCB}), then the run-exit
     * ones if the cycle was running ({@link #addRunExitCB}).
     *
     * @return true, as ARIA's answers when there is no connection to close or it closed
     */
    @Override
    public boolean disconnect() {
        if (events.claimEnd()) {
            if (ariaConnectionLines) {
                ArLog.log(ArLog.Terse, "Disconnecting from robot.");
            } else {
                LOG.info(() -> "robot " + getName() + ": Disconnecting from robot.");
            }
            events.disconnectNormally.invoke(getName());
            super.disconnect();
            loopExited();
        } else {
            events.isStabilizing = false;
            super.disconnect();
        }
        return true;
    }

    /**
     * ARIA's {@code ArRobot::dropConnection} (ArRobot.cpp): leaves the run as a lost connection does, with the
     * disconnect-on-error callbacks ({@link #addDisconnectOnErrorCB}) instead of the normal ones;
     * nothing when the robot is not connected.
     *
     * @param technicalReason why, for the log and {@link #getDropConnectionReason()}; null for ARIA's default
     * @param userReason      why, for a user ({@link #getDropConnectionUserReason()}); null for the technical one
     */
    public void dropConnection(String technicalReason, String userReason) {
        if (!isConnected() || !events.claimEnd()) {
            return;
        }
        events.dropReason = technicalReason != null ? technicalReason
                : "Lost connection to the microcontroller because of unknown error.";
        events.dropUserReason = userReason != null ? userReason : events.dropReason;
        LOG.warning(() -> "robot " + getName() + ": " + events.dropReason);
        events.disconnectOnError.invoke(getName());
        super.disconnect();
        loopExited();
    }

    /** As {@link #dropConnection(String, String)} with ARIA's default reason. */
    public void dropConnection() {
        dropConnection(null, null);
    }

    /** @return why the connection was dropped (ARIA's technical reason); empty if it was not */
    public String getDropConnectionReason() {
        return events.dropReason;
    }

    /** @return why the connection was dropped, for a user; empty if it was not */
    public String getDropConnectionUserReason() {
        return events.dropUserReason;
    }

    /**
     * Tells the end of the run once, when the program sees it (after a yield): the
     * disconnect-on-error callbacks if the robot was dropped or lost ({@link RunEnd.Kind#isFailure()}),
     * with its description as the drop reason, else the disconnect-normally ones; then the run-exit ones.
     */
    void noticeEnd() {
        if (super.isConnected() || !events.claimEnd()) {
            return;
        }
        RunEnd end = getRunEnd();
        if (end != null && end.kind().isFailure()) {
            events.dropReason = end.describe();
            events.dropUserReason = end.reason();
            // the program's launcher, or its RunEnd, says so to the user: logged here only for detail
            LOG.fine(() -> "robot " + getName() + ": " + events.dropReason);
            events.disconnectOnError.invoke(getName());
        } else {
            events.disconnectNormally.invoke(getName());
        }
        loopExited();
    }

    /** The cycle stopped: the run-exit callbacks, once, if it was running (ARIA's sync loop's exit). */
    void loopExited() {
        boolean was = runningAsync;
        runningAsync = false;
        if (was) {
            events.runExit.invoke(getName());
        }
        events.runExited();
    }

    /**
     * ARIA's connection steps, run when the Environment has welcomed the robot: the opened time,
     * then stabilizing ({@link #addStabilizingCB}), finished at once when the stabilizing time is 0
     * (ARIA's default), else by the cycle once it has passed; and the sonar cycle the parameter file
     * gives ({@link ArRobot#getSonarCycle()}).
     */
    @Override
    protected void welcomed(RobotState initial) {
        if (ariaConnectionLines) {
            logConnected();
        }
        events.openedMs = initial.timeMs();
        if (sonarCycleMs > 0) {
            request(new Command.SetSonarCycle(sonarCycleMs));
        }
        if (runningAsync && super.isConnected()) {
            keepAlive(true);
        }
        events.isStabilizing = true;
        events.stabilizingStartMs = initial.timeMs();
        events.stabilizing.invoke(getName());
        if (events.stabilizingTimeMs == 0) {
            finishedConnection();
        }
    }

    /** An ARIA connector connects the robot: it logs ARIA's lines as it connects and disconnects. */
    void logConnectionAsAria() {
        ariaConnectionLines = true;
    }

    /**
     * @param file the parameter file the robot's parameters were read from: a shipped name (ARIA's
     *             default parameters for the type) or a path; null when they were given as a record
     */
    void parametersFrom(String file) {
        parameterFile = file;
    }

    /**
     * ARIA's lines once the robot's server has answered ({@code ArRobot::asyncConnectHandler} and
     * {@code processParamFile}, ArRobot.cpp): who the robot is, from its parameters.
     */
    private void logConnected() {
        ArLog.log(ArLog.Terse, "Connected to robot.");
        ArLog.log(ArLog.Normal, "Name: %s", getRobotName());
        ArLog.log(ArLog.Normal, "Type: %s", getRobotType());
        ArLog.log(ArLog.Normal, "Subtype: %s", getRobotSubType());
        String file = parameterFile;
        if (file != null && RobotParameterFiles.shippedNames().contains(file)) {
            // a shipped file is RoboSim's own parameters for the type, as ARIA's built-in defaults
            ArLog.log(ArLog.Normal, "Using default parameters for a %s robot", getRobotSubType());
        } else if (file != null) {
            ArLog.log(ArLog.Normal, "Loaded robot parameters from %s", file);
        }
        ArLog.log(ArLog.Normal, "Robot Serial Number: %s", getRobotSerialNumber());
    }

    /**
     * ARIA's {@code ArRobot::finishedConnection} (ArRobot.cpp): connected; the trip odometer restarts;
     * the connect callbacks; the waiters.
     */
    void finishedConnection() {
        events.isStabilizing = false;
        restartTripOdometer();
        events.connected();
        events.connect.invoke(getName());
    }

    // ---- who the robot is ----

    /**
     * @return the robot's name as the robot reports it (ARIA's {@code ArRobot::getRobotName}
     *     (ArRobot.h)): its name in the world, or, through a Pioneer robot server, the name the server
     *     gives it in its handshake
     */
    public String getRobotName() {
        return getServerRobotName();
    }

    /**
     * @return the robot's class from its parameters, for example {@code Pioneer} (ARIA's {@code
     *     ArRobot::getRobotType} (ArRobot.h))
     */
    public String getRobotType() {
        return getParameters().robotClass();
    }

    /**
     * @return the robot's subclass from its parameters, for example {@code p3dx} (ARIA's {@code
     *     ArRobot::getRobotSubType} (ArRobot.h))
     */
    public String getRobotSubType() {
        return getParameters().subclass();
    }

    /**
     * @return {@code SIM}: the serial number a simulated robot gives, as MobileSim's and RoboSim's
     *     Pioneer port's CONFIG packets do (ARIA's {@code ArRobot::getRobotSerialNumber}, ArRobot.h)
     */
    public String getRobotSerialNumber() {
        return "SIM";
    }

    /**
     * Renames the robot before it connects, as ARIA's {@code ArRobot::setName} (ArRobot.cpp); null gives
     * ARIA's default name ({@code robot}, {@code robot2}, ...). Once connected the world knows it by its
     * name, so the rename is refused with a log line.
     *
     * @param name the new name, or null
     */
    public void setName(String name) {
        if (super.isConnected()) {
            LOG.warning(() -> "robot " + getName() + ": setName(" + name
                    + "): the robot is connected under its name; ignoring it");
            return;
        }
        // the parameters stay, and with them the limits set
        super.relocate(name != null ? name : defaultName(), getHost(), getPort(), getParameters());
    }

    // ---- connection callbacks and waits ----

    /** @param functor run when the robot has connected (after stabilizing), last in the list */
    public void addConnectCB(Runnable functor) {
        addConnectCB(functor, ArListPos.LAST);
    }

    /**
     * Adds a connect callback, as ARIA's {@code addConnectCB} (ArRobot.cpp).
     *
     * @param functor  run in the connecting thread when the robot has connected
     * @param position {@link ArListPos#FIRST} or {@link ArListPos#LAST}; another is ignored with a log line
     */
    public void addConnectCB(Runnable functor, int position) {
        events.connect.add(functor, position);
    }

    /** @param functor a connect callback to remove */
    public void remConnectCB(Runnable functor) {
        events.connect.remove(functor);
    }

    /** @param functor run when {@link #blockingConnect()} fails, last in the list */
    public void addFailedConnectCB(Runnable functor) {
        addFailedConnectCB(functor, ArListPos.LAST);
    }

    /** @param functor run when a connection fails @param position {@link ArListPos#FIRST} or {@link ArListPos#LAST} */
    public void addFailedConnectCB(Runnable functor, int position) {
        events.failedConnect.add(functor, position);
    }

    /** @param functor a failed-connect callback to remove */
    public void remFailedConnectCB(Runnable functor) {
        events.failedConnect.remove(functor);
    }

    /** @param functor run when the robot leaves normally, last in the list */
    public void addDisconnectNormallyCB(Runnable functor) {
        addDisconnectNormallyCB(functor, ArListPos.LAST);
    }

    /**
     * @param functor  run when the robot leaves normally: {@link #disconnect()}, or the Environment
     *                 ended the run (seen at the program's next yield)
     * @param position {@link ArListPos#FIRST} or {@link ArListPos#LAST}
     */
    public void addDisconnectNormallyCB(Runnable functor, int position) {
        events.disconnectNormally.add(functor, position);
    }

    /** @param functor a disconnect-normally callback to remove */
    public void remDisconnectNormallyCB(Runnable functor) {
        events.disconnectNormally.remove(functor);
    }

    /** @param functor run when the connection is lost or dropped, last in the list */
    public void addDisconnectOnErrorCB(Runnable functor) {
        addDisconnectOnErrorCB(functor, ArListPos.LAST);
    }

    /**
     * @param functor  run when the connection is lost, or the Environment drops the robot (seen at
     *                 the program's next yield), or {@link #dropConnection} is called
     * @param position {@link ArListPos#FIRST} or {@link ArListPos#LAST}
     */
    public void addDisconnectOnErrorCB(Runnable functor, int position) {
        events.disconnectOnError.add(functor, position);
    }

    /** @param functor a disconnect-on-error callback to remove */
    public void remDisconnectOnErrorCB(Runnable functor) {
        events.disconnectOnError.remove(functor);
    }

    /** @param functor run when the robot's cycle stops, last in the list */
    public void addRunExitCB(Runnable functor) {
        addRunExitCB(functor, ArListPos.LAST);
    }

    /**
     * @param functor  run once when a cycle started by {@link ArRobot#run()} or {@link ArRobot#runAsync()} stops:
     *                 {@link ArRobot#stopRunning}, or the robot leaves the run
     * @param position {@link ArListPos#FIRST} or {@link ArListPos#LAST}
     */
    public void addRunExitCB(Runnable functor, int position) {
        events.runExit.add(functor, position);
    }

    /** @param functor a run-exit callback to remove */
    public void remRunExitCB(Runnable functor) {
        events.runExit.remove(functor);
    }

    /** @param functor run when the robot starts stabilizing after the Environment's welcome, last in the list */
    public void addStabilizingCB(Runnable functor) {
        addStabilizingCB(functor, ArListPos.LAST);
    }

    /**
     * @param functor run when the robot starts stabilizing
     * @param position {@link ArListPos#FIRST} or {@link ArListPos#LAST}
     */
    public void addStabilizingCB(Runnable functor, int position) {
        events.stabilizing.add(functor, position);
    }

    /** @param functor a stabilizing callback to remove */
    public void remStabilizingCB(Runnable functor) {
        events.stabilizing.remove(functor);
    }

    /** @return whether the robot is stabilizing: welcomed, but its stabilizing time has not passed */
    public boolean isStabilizing() {
        return events.isStabilizing;
    }

    /**
     * @param mSecs how long after the welcome the robot stabilizes before it counts as connected,
     *              simulated ms; 0 or less means 0 (ARIA's default), as in ARIA
     */
    public void setStabilizingTime(int mSecs) {
        events.stabilizingTimeMs = Math.max(0, mSecs);
    }

    /** @return the stabilizing time, ms */
    public int getStabilizingTime() {
        return events.stabilizingTimeMs;
    }

    /** @return as {@link #waitForConnect(long)} with no time limit */
    public WaitState waitForConnect() {
        return waitForConnect(0);
    }

    /**
     * Waits until another thread has connected the robot, as ARIA's {@code ArRobot::waitForConnect}
     * (ArRobot.cpp); before a connection there is no simulated time, so the wait is in wall-clock time.
     *
     * @param msecs at most this many ms; 0 for no limit
     * @return {@link WaitState#WAIT_CONNECTED} at once if connected, or once connected (or woken by
     *         {@link #wakeAllConnWaitingThreads()}, as in ARIA); {@link WaitState#WAIT_TIMEDOUT};
     *         {@link WaitState#WAIT_INTR} if interrupted
     */
    public WaitState waitForConnect(long msecs) {
        if (isConnected()) {
            return WaitState.WAIT_CONNECTED;
        }
        return switch (events.await(ConnectionEvents.Kind.CONN, this::isConnected, msecs)) {
            case 0 -> WaitState.WAIT_CONNECTED;
            case 1 -> WaitState.WAIT_TIMEDOUT;
            default -> WaitState.WAIT_INTR;
        };
    }

    /** @return as {@link #waitForConnectOrConnFail(long)} with no time limit */
    public WaitState waitForConnectOrConnFail() {
        return waitForConnectOrConnFail(0);
    }

    /**
     * As {@link #waitForConnect(long)}, also ending when a connection fails.
     *
     * @param msecs at most this many wall-clock ms; 0 for no limit
     * @return {@link WaitState#WAIT_CONNECTED}, {@link WaitState#WAIT_FAILED_CONN} (failed, or woken
     *         while not connected), {@link WaitState#WAIT_TIMEDOUT} or {@link WaitState#WAIT_INTR}
     */
    public WaitState waitForConnectOrConnFail(long msecs) {
        if (isConnected()) {
            return WaitState.WAIT_CONNECTED;
        }
        return switch (events.await(ConnectionEvents.Kind.CONN_OR_FAIL, this::isConnected, msecs)) {
            case 0 -> isConnected() ? WaitState.WAIT_CONNECTED : WaitState.WAIT_FAILED_CONN;
            case 1 -> WaitState.WAIT_TIMEDOUT;
            default -> WaitState.WAIT_INTR;
        };
    }

    /** Wakes every thread in {@link #waitForConnect}, {@link #waitForConnectOrConnFail} and {@link ArRobot#waitForRunExit}. */
    public void wakeAllWaitingThreads() {
        wakeAllConnWaitingThreads();
        wakeAllRunExitWaitingThreads();
    }

    /** Wakes the threads in {@link #waitForConnect} and {@link #waitForConnectOrConnFail}. */
    public void wakeAllConnWaitingThreads() {
        events.wakeConn();
        events.wakeConnOrFail();
    }

    /** Wakes the threads in {@link #waitForConnectOrConnFail}. */
    public void wakeAllConnOrFailWaitingThreads() {
        events.wakeConnOrFail();
    }

    /** Wakes the threads in {@link ArRobot#waitForRunExit}. */
    public void wakeAllRunExitWaitingThreads() {
        events.wakeRunExit();
    }

    /** @return the simulated time the Environment welcomed the robot (0 before) */
    public ArTime getConnectionOpenedTime() {
        return timeAt(events.openedMs);
    }

    /** @return the simulated time of the latest state the Environment sent (each step's state is ARIA's packet) */
    public ArTime getLastPacketTime() {
        return timeAt(state().timeMs());
    }

    /** @return the simulated time of the latest odometry: the latest state's, as every state carries the pose */
    public ArTime getLastOdometryTime() {
        return timeAt(state().timeMs());
    }

    /**
     * ARIA's {@code ArRobot::setConnectionTimeoutTime} (ArRobot.cpp), logged as ARIA logs it; 0 or less
     * means 0. The value is answered by {@link #getConnectionTimeoutTime()}; the robot itself counts the
     * Environment lost after the hardware's lost time ({@code robosim.hw.HardwareOptions}, 10 s of
     * wall-clock silence by default), since simulated time stops when the Environment does.
     *
     * @param mSecs the timeout, ms
     */
    public void setConnectionTimeoutTime(int mSecs) {
        LOG.info(() -> "robot " + getName() + ": ArRobot::setConnectionTimeoutTime: Setting timeout to "
                + mSecs + " mSecs");
        events.timeoutMs = Math.max(0, mSecs);
    }

    /** @return the connection timeout set, ms (ARIA's default 8000) */
    public int getConnectionTimeoutTime() {
        return events.timeoutMs;
    }

    /** @return an {@link ArTime} at a simulated time */
    static ArTime timeAt(long ms) {
        ArTime t = new ArTime();
        t.setSec(ms / 1000);
        t.setMSec(ms % 1000);
        return t;
    }
}
