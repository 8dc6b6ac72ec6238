package robosim.aria;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.locks.ReentrantLock;
import robosim.hw.AbstractRobot;
import robosim.hw.HardwareOptions;
import robosim.params.RobotParameterFiles;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.Command;
import robosim.protocol.RobotState;
import robosim.protocol.RobotParameters;

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

    private final SonarRing sonar;
    private final ReentrantLock lock = new ReentrantLock();
    private final TaskList sensorInterpTasks = new TaskList("sensor interpretation");
    private final TaskList userTasks = new TaskList("user");
    private final List<ArRangeDevice> rangeDevices = new CopyOnWriteArrayList<>();
    private volatile long counter;
    private volatile boolean sonarEnabled = true;
    private volatile boolean runningAsync;
    private volatile ArPose moveStart;
    private volatile double moveDistance;
    private volatile Double headingTarget;
    private volatile double maxTransVel;
    private final DriveLimits driveLimits = new DriveLimits();
    private final Odometer odometer = new Odometer();
    private volatile double moveDoneDist = DEFAULT_MOVE_DONE;
    private volatile double headingDoneDiff = DEFAULT_HEADING_DONE;
    private volatile double stoppedVel = STOPPED_VEL;
    private volatile double stoppedRotVel = STOPPED_ROT_VEL;
    private volatile double maxRotVel;

    /**
     * @param name      the robot's name in the world
     * @param host      the Environment's host
     * @param port      the Environment's robot port
     * @param paramFile the robot's parameter file: a path, or a shipped name such as {@code p3dx}
     */
    public ArRobot(String name, String host, int port, String paramFile) {
        this(name, host, port, RobotParameterFiles.load(paramFile));
    }

    /**
     * @param name       the robot's name in the world
     * @param host       the Environment's host
     * @param port       the Environment's robot port
     * @param parameters the robot's parameters
     */
    public ArRobot(String name, String host, int port, RobotParameters parameters) {
        super(name, host, port, "pioneer", parameters);
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
        return tryConnect(HardwareOptions.defaults());
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
     * counter goes up, the sonar readings are taken, then the sensor-interpretation tasks and the
     * user tasks run, all under the robot's lock, as ARIA's cycle does.
     */
    @Override
    protected void responded(RobotSensorResponse response) {
        lock.lock();
        try {
            super.responded(response);
            counter++;
            RobotState s = response.state();
            sonar.update(s.sonar(), new ArPose(s.x(), s.y(), s.th()), counter, s.timeMs());
            odometer.update(s);
            sensorInterpTasks.runAll(getName());
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
        runningAsync = true;
        keepAlive(true);
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

    /** Waits, yielded, until the robot is disconnected. */
    public void waitForRunExit() {
        while (isConnected()) {
            sleepSimulated(Long.MAX_VALUE / 4);
        }
    }

    // ---- range devices ----

    /** @param device a range device to attach; its robot becomes this one */
    public void addRangeDevice(ArRangeDevice device) {
        device.setRobot(this);
        rangeDevices.add(device);
    }

    /** @param device a range device to detach; its robot is cleared */
    public void remRangeDevice(ArRangeDevice device) {
        if (rangeDevices.remove(device)) {
            device.setRobot(null);
        }
    }

    /** @param name a device's name @return the first attached device of that name, or null */
    public ArRangeDevice findRangeDevice(String name) {
        return rangeDevices.stream().filter(d -> d.getName().equals(name)).findFirst().orElse(null);
    }

    /** @return the attached range devices */
    public List<ArRangeDevice> getRangeDeviceList() {
        return List.copyOf(rangeDevices);
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
    }

    /** Translational and rotational velocity to zero at once. */
    public void stop() {
        moveStart = null;
        headingTarget = null;
        request(new Command.Stop());
    }

    /**
     * @param velocity mm/s, rounded and clamped to the maximum translational velocity
     * @throws IllegalArgumentException if it is not finite
     */
    public void setVel(double velocity) {
        Command.SetVel vel = new Command.SetVel(Math.rint(velocity));
        moveStart = null;
        request(vel);
    }

    /**
     * @param velocity deg/s, counter-clockwise positive, clamped to the maximum rotational velocity
     * @throws IllegalArgumentException if it is not finite
     */
    public void setRotVel(double velocity) {
        Command.SetRotVel rotVel = new Command.SetRotVel(velocity);
        headingTarget = null;
        request(rotVel);
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
    }

    /**
     * @param heading absolute heading to turn to, degrees
     * @throws IllegalArgumentException if it is not finite
     */
    public void setHeading(double heading) {
        Command.SetHeading turn = new Command.SetHeading(heading);
        headingTarget = ArMath.fixAngle(heading);
        request(turn);
    }

    /**
     * @param delta degrees to turn from the current heading
     * @throws IllegalArgumentException if it is not finite
     */
    public void setDeltaHeading(double delta) {
        Command.SetDeltaHeading turn = new Command.SetDeltaHeading(delta);
        headingTarget = ArMath.fixAngle(getTh() + delta);
        request(turn);
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

    /** @return odometry x, mm */
    public double getX() {
        return state().x();
    }

    /** @return odometry y, mm */
    public double getY() {
        return state().y();
    }

    /** @return odometry heading, degrees in (-180, 180] */
    public double getTh() {
        return state().th();
    }

    /** @return the odometry pose, a new object */
    public ArPose getPose() {
        RobotState s = state();
        return new ArPose(s.x(), s.y(), s.th());
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

    /** @return whether either wheel is stalled; both are, when RoboSim stalls a robot */
    public boolean isLeftMotorStalled() {
        return isStalled();
    }

    /** @return whether either wheel is stalled; both are, when RoboSim stalls a robot */
    public boolean isRightMotorStalled() {
        return isStalled();
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
