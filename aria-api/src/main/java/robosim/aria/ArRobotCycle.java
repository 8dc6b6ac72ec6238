package robosim.aria;

import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Supplier;
import robosim.aria.ArRobot.WaitState;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.Command;
import robosim.protocol.RobotParameters;
import robosim.protocol.RobotState;

/**
 * {@link ArRobot}'s cycle: what each step's state starts (the counter, the readings, the
 * sensor-interpretation tasks, the actions, the user tasks, under the robot's lock), running it
 * ({@code run}, {@code runAsync}, {@code loopOnce}, {@code stopRunning}), the task lists, the lock,
 * and the logging of what is sent and received, as ARIA's {@code ArRobot} has them (ArRobot.cpp). One
 * of the package-private layers that {@link ArRobot}, the public face, is made of.
 */
abstract class ArRobotCycle extends ArRobotConnection {
    /** The robot's lock ({@link #lock()}): the cycle holds it while it updates the robot and runs its tasks. */
    final ReentrantLock lock = new ReentrantLock();
    private final TaskList sensorInterpTasks = new TaskList("sensor interpretation");
    private final TaskList userTasks = new TaskList("user");
    /** The cycle counter ({@link #getCounter()}). */
    volatile long counter;

    /** Set by {@link #loopOnce()} on a robot not run: its program runs the cycle, not the states' arrival. */
    private volatile boolean programCycles;
    /** The actions and the direct motion commands' hold on them (every robot of these layers is an ArRobot). */
    final ActionDriver actions = new ActionDriver((ArRobot) this);
    /** The robot's cycle's extras: warning time, counts of states per simulated second. */
    final CycleStats cycleStats = new CycleStats();
    /** The robot's charge and IO, as far as a program sets them. */
    final Extras extras = new Extras();
    /** Set by {@link ArRobot#forceTryingToMove()}, undone at the end of each cycle. */
    volatile boolean forcedTryingToMove;
    private volatile boolean cycleStopped;

    /** The robot, named and placed, with its parameters: see {@link ArRobot}'s constructors. */
    ArRobotCycle(String name, String host, int port, RobotParameters parameters) {
        super(name, host, port, parameters);
    }

    /**
     * Takes one state's readings into the robot (sonar, odometers, encoders, battery, pose histories),
     * at the start of the cycle, under the robot's lock; the layers above keep them.
     *
     * @param s the state of the step
     */
    abstract void readState(RobotState s);

    // ---- the cycle ----

    /**
     * One robot cycle, run as each step's state arrives (while the robot's code is yielded): the
     * counter goes up, the sonar readings are taken, then the sensor-interpretation tasks, the
     * actions (resolved and sent, see {@link ArRobot#addAction}) and the user tasks run, in ARIA's task
     * order, all under the robot's lock, as ARIA's cycle does. Before them the pose histories take
     * the cycle's poses ({@link ArRobot#getPoseInterpPosition}) and a stabilizing robot whose stabilizing
     * time has passed becomes connected; after them {@link ArRobot#forceTryingToMove()} is undone and a
     * cycle slower than {@link #getCycleWarningTime()} in wall-clock time is logged. Once the program
     * runs the cycle itself ({@link #loopOnce()}), the state only updates the robot here: the counter
     * and the tasks are the program's calls'.
     */
    @Override
    protected void responded(RobotSensorResponse response) {
        lock.lock();
        try {
            super.responded(response);
            if (cycleStopped) {
                return;
            }
            long began = System.nanoTime();
            boolean byProgram = programCycles && !runningAsync;
            if (!byProgram) {
                counter++;
            }
            RobotState s = response.state();
            readState(s);
            if (events.isStabilizing && s.timeMs() - events.stabilizingStartMs > events.stabilizingTimeMs) {
                finishedConnection();
            }
            if (!byProgram) {
                runTasks(s.timeMs());
            }
            forcedTryingToMove = false;
            cycleStats.cycleTook(System.nanoTime() - began, getName());
        } finally {
            lock.unlock();
        }
    }

    /** The tasks of one cycle: sensor interpretation, the actions, the user tasks. */
    private void runTasks(long timeMs) {
        sensorInterpTasks.runAll(getName());
        actions.cycle(timeMs);
        userTasks.runAll(getName());
    }

    /** @return the cycle counter: one more for every step's state received */
    public long getCounter() {
        return counter;
    }

    /** Adds one to the cycle counter, as ARIA's {@code ArRobot::incCounter} (ArRobot.h). */
    public void incCounter() {
        counter++;
    }

    /**
     * Runs the robot's cycle once, as ARIA's {@code ArRobot::loopOnce} (ArRobot.cpp) runs its task
     * tree once, for a program that drives the cycle itself instead of {@link #run()} or
     * {@link #runAsync()} (ARIA's single-threaded robot, singleThreadLoopExample.cpp): the
     * sensor-interpretation tasks, the actions (their commands queued for the next step) and the user
     * tasks, on the calling thread under the robot's lock; then the counter goes up. From the first
     * call on a connected robot that is not running, the steps' states only update the robot (as
     * ARIA's packets, read in the next call) and the cycle runs in these calls alone, once per call.
     * It does not wait: ARIA's non-threaded packet handler ({@code ArRobot::packetHandlerNonThreaded})
     * waits for a SIP only while the robot is running; here the states arrive while the program
     * sleeps ({@link ArUtil#sleep}), so a loop that sleeps a step between calls runs a cycle a step.
     */
    public void loopOnce() {
        if (!runningAsync && linkConnected()) {
            programCycles = true;
        }
        underLock(() -> {
            runTasks(simulatedMs());
            counter++;
        });
    }

    /**
     * @return the cycle time, ms: the robot's cycle is the world's step (ARIA's cycle chained to its
     *         packets), so the step length (100 before connecting, ARIA's default)
     */
    public int getCycleTime() {
        return getStepMs();
    }

    /**
     * ARIA's {@code ArRobot::setCycleTime} (ArRobot.cpp): here the cycle is the world's step, one cycle per state the
     * Environment sends, so the value is ignored with a log line; the world file sets the step.
     *
     * @param ms the cycle time ARIA would use
     */
    public void setCycleTime(int ms) {
        LOG.info(() -> "robot " + getName() + ": setCycleTime(" + ms + "): the robot's cycle is the world's step of "
                + getStepMs() + " ms; ignoring it");
    }

    /** @return the cycle warning time, ms (ARIA's default 250; 0 means no warnings) */
    public int getCycleWarningTime() {
        return cycleStats.warningMs;
    }

    /**
     * @param ms a cycle whose tasks take longer than this, in wall-clock time, is logged (it holds
     *           the whole simulation); 0 for never, as in ARIA
     */
    public void setCycleWarningTime(int ms) {
        cycleStats.warningMs = ms;
    }

    /** @return whether the current cycle will not be logged as slow ({@link #setNoTimeWarningThisCycle}) */
    public boolean getNoTimeWarningThisCycle() {
        return cycleStats.noTimeWarningThisCycle;
    }

    /** @param noTimeWarningThisCycle whether the current cycle is not to be logged as slow; cleared after the cycle */
    public void setNoTimeWarningThisCycle(boolean noTimeWarningThisCycle) {
        cycleStats.noTimeWarningThisCycle = noTimeWarningThisCycle;
    }

    /**
     * @return true: the cycle is chained to the states' arrival, each step's state starting one, as
     *     ARIA's is by default
     */
    public boolean isCycleChained() {
        return true;
    }

    /**
     * ARIA's {@code ArRobot::setCycleChained} (ArRobot.h): the cycle is always chained to the states here (there is no
     * timer to run it between steps), so false is ignored with a log line.
     *
     * @param cycleChained whether the cycle follows the states
     */
    public void setCycleChained(boolean cycleChained) {
        if (!cycleChained) {
            LOG.info(() -> "robot " + getName()
                    + ": setCycleChained(false): the cycle runs once per step's state; ignoring it");
        }
    }

    /** @return the states the Environment sent in the last whole simulated second (ARIA's motor packets a second) */
    public int getMotorPacCount() {
        return cycleStats.motorPacCount(simulatedMs());
    }

    /** @return the states with sonar readings in the last whole simulated second (ARIA's sonar packets a second) */
    public int getSonarPacCount() {
        return cycleStats.sonarPacCount(simulatedMs());
    }

    /**
     * Lets the robot's cycle (its tasks) go on when the program's threads end: the robot then stays
     * in the run until the Environment ends it or {@link #disconnect()} is called. The cycle itself
     * always runs, on the robot's hardware thread.
     */
    public void runAsync() {
        cycleStopped = false;
        runningAsync = true;
        if (linkConnected()) {
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

    /** @return as {@link #waitForRunExit(long)} with no time limit */
    public WaitState waitForRunExit() {
        return waitForRunExit(0);
    }

    /**
     * Waits, yielded, until the robot's cycle stops ({@link #stopRunning}, or the robot leaves the
     * run), as ARIA's {@code ArRobot::waitForRunExit} (ArRobot.cpp).
     *
     * @param msecs at most this many simulated ms; 0 for no limit
     * @return {@link WaitState#WAIT_RUN_EXIT} once the cycle has stopped (or the wait was woken by
     *         {@link #wakeAllRunExitWaitingThreads()}, as in ARIA), else {@link WaitState#WAIT_TIMEDOUT}
     */
    public WaitState waitForRunExit(long msecs) {
        long start = getSimTimeMs();
        long wakes = events.runExitEvents();
        while (linkConnected() && !cycleStopped && events.runExitEvents() == wakes) {
            if (msecs > 0 && getSimTimeMs() - start >= msecs) {
                return WaitState.WAIT_TIMEDOUT;
            }
            sleepSimulated(getStepMs());
        }
        noticeEnd();
        return WaitState.WAIT_RUN_EXIT;
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
     * follow the Environment's state. If the cycle was running ({@link #run()}, {@link #runAsync()})
     * the run-exit callbacks run, after the disconnect-normally ones when disconnecting, as in ARIA.
     *
     * @param doDisconnect whether to leave the run too
     */
    public void stopRunning(boolean doDisconnect) {
        cycleStopped = true;
        if (linkConnected()) {
            keepAlive(false);
        }
        if (doDisconnect) {
            disconnect();
        }
        loopExited();
    }

    // ---- tasks ----

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

    /** @param functor the body of the user task to remove @return whether it was there */
    public boolean remUserTask(Runnable functor) {
        return userTasks.remove(functor);
    }

    /** @param name a user task's name @return the task, or null (ARIA's {@code ArRobot::findUserTask} (ArRobot.cpp)) */
    public ArSyncTask findUserTask(String name) {
        return userTasks.find(name);
    }

    /** @param functor a user task's body @return the task, or null */
    public ArSyncTask findUserTask(Runnable functor) {
        return userTasks.find(functor);
    }

    /**
     * @param name a task's name
     * @return the sensor-interpretation or user task of that name (in that order, as ARIA's task
     *         tree has them), or null
     */
    public ArSyncTask findTask(String name) {
        ArSyncTask t = sensorInterpTasks.find(name);
        return t != null ? t : userTasks.find(name);
    }

    /** @param functor a task's body @return the sensor-interpretation or user task with it, or null */
    public ArSyncTask findTask(Runnable functor) {
        ArSyncTask t = sensorInterpTasks.find(functor);
        return t != null ? t : userTasks.find(functor);
    }

    /** Logs the user tasks in running order (ARIA's {@code ArRobot::logUserTasks} (ArRobot.cpp)). */
    public void logUserTasks() {
        userTasks.log(getName());
    }

    /** Logs every task of the cycle in running order: the sensor-interpretation tasks, then the user tasks. */
    public void logAllTasks() {
        sensorInterpTasks.log(getName());
        userTasks.log(getName());
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

    /** @param functor the body of the sensor-interpretation task to remove @return whether it was there */
    public boolean remSensorInterpTask(Runnable functor) {
        return sensorInterpTasks.remove(functor);
    }

    // ---- the robot's lock ----

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
        noticeEnd();
    }

    /** @return whether the calling thread holds the robot's lock */
    boolean isLockedByMe() {
        return lock.isHeldByCurrentThread();
    }

    /** @return what the read gives, taken under the robot's lock */
    <T> T underLock(Supplier<T> read) {
        lock.lock();
        try {
            return read.get();
        } finally {
            lock.unlock();
        }
    }

    /** Does a change under the robot's lock. */
    void underLock(Runnable change) {
        lock.lock();
        try {
            change.run();
        } finally {
            lock.unlock();
        }
    }

    long simulatedMs() {
        return state().timeMs();
    }

    // ---- logging what is sent and received ----

    /** @return whether every motion command sent is logged */
    public boolean getLogMovementSent() {
        return extras.logMovementSent;
    }

    /** @param logMovementSent whether every motion command sent is logged, as ARIA's "Non-action ..." lines */
    public void setLogMovementSent(boolean logMovementSent) {
        extras.logMovementSent = logMovementSent;
    }

    /** @return whether every cycle's pose is logged */
    public boolean getLogMovementReceived() {
        return extras.logMovementReceived;
    }

    /** @param logMovementReceived whether every cycle logs the pose it received */
    public void setLogMovementReceived(boolean logMovementReceived) {
        extras.logMovementReceived = logMovementReceived;
    }

    /** @return whether every cycle's velocities are logged */
    public boolean getLogVelocitiesReceived() {
        return extras.logVelocitiesReceived;
    }

    /** @param logVelocitiesReceived whether every cycle logs the velocities and heading it received */
    public void setLogVelocitiesReceived(boolean logVelocitiesReceived) {
        extras.logVelocitiesReceived = logVelocitiesReceived;
    }

    /** @return whether every state's whole content is logged (ARIA's SIP contents) */
    public boolean getLogSIPContents() {
        return extras.logSipContents;
    }

    /** @param logSIP whether every cycle logs the whole state it received */
    public void setLogSIPContents(boolean logSIP) {
        extras.logSipContents = logSIP;
    }

    /** @return whether every state received is logged (its step and time) */
    public boolean getPacketsReceivedTracking() {
        return extras.packetsReceivedTracking;
    }

    /** @param packetsReceivedTracking whether every state received is logged, as ARIA tracks packets */
    public void setPacketsReceivedTracking(boolean packetsReceivedTracking) {
        LOG.info(() -> "robot " + getName() + ": ArRobot: " + (packetsReceivedTracking ? "" : "not ")
                + "tracking packets received");
        extras.packetsReceivedTracking = packetsReceivedTracking;
    }

    /** @return whether every request sent is logged */
    public boolean getPacketsSentTracking() {
        return extras.packetsSentTracking;
    }

    /** @param packetsSentTracking whether every request sent is logged, with ARIA's log line on change */
    public void setPacketsSentTracking(boolean packetsSentTracking) {
        LOG.info(() -> "robot " + getName() + ": ArRobot: " + (packetsSentTracking ? "" : "not ")
                + "tracking packets sent");
        extras.packetsSentTracking = packetsSentTracking;
    }

    /**
     * Queues a request, logging it when {@link #setPacketsSentTracking} or (for motion) {@link
     * #setLogMovementSent} says so.
     */
    @Override
    protected void request(Command command) {
        if (extras.packetsSentTracking || extras.logMovementSent && command instanceof Command.Motion) {
            LOG.info(() -> "robot " + getName() + ": sent " + command);
        }
        super.request(command);
    }
}
