package robosim.scout;

import static robosim.scout.NomadUnits.headingToTenthDeg;
import static robosim.scout.NomadUnits.mmToTenthInch;
import static robosim.scout.NomadUnits.tenthDegToDeg;
import static robosim.scout.NomadUnits.tenthInchToMm;

import java.util.Arrays;
import java.util.function.BiConsumer;
import java.util.logging.Logger;
import robosim.hw.AbstractRobot;
import robosim.hw.HardwareOptions;
import robosim.params.RobotParameterFiles;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.Bumpers;
import robosim.protocol.Command;
import robosim.protocol.RobotKind;
import robosim.protocol.RobotState;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarReading;

/**
 * The Nomadic Scout Robot-Object: the Nomad client library's calls, with their names, arguments and
 * units (1/10 inch, 1/10 degree; see {@link NomadUnits}), on one robot. Where the C library returns
 * {@code TRUE} or {@code FALSE}, these calls return {@code true} or {@code false}: false when the
 * robot is not connected, when an argument is out of range (nothing is sent then), and for the
 * calls a Scout does not support ({@link #pa}, {@link #conf_ir}, {@link #conf_cp}), as on the real
 * robot.
 *
 * <p>Time: the calls that ask the robot for data ({@link #gs}, {@link #get_sn}, {@link #get_bp},
 * {@link #get_rc}, {@link #get_rv}) wait, yielding, for the next step's state, as the C library
 * waited for the robot's reply: a loop around {@code gs()} runs once per step. The motion and
 * configuration calls do not block; they are sent with the step's requests. {@link #ws} waits in
 * simulated time.
 *
 * <pre>{@code
 * Scout scout = new Scout(name, host, port);
 * if (!scout.connect_robot()) return;
 * scout.pr(1000, 1000, 0);          // 100 inches ahead, both wheels
 * scout.ws(1, 1, 0, 30);            // wait until both wheels have stopped, at most 30 s
 * scout.gs();
 * long ahead = scout.State[StateVector.STATE_SONAR_0];   // inches
 * scout.disconnect_robot();
 * }</pre>
 */
public class Scout extends AbstractRobot {
    /** The Scout's rotation constant: 1/10 inch of wheel travel per 1/10 degree of turn. */
    public static final double ROTATION_CONSTANT = 0.118597;
    /** The shipped Scout's parameter file. */
    public static final String DEFAULT_PARAMETERS = RobotKind.SCOUT.defaultParameters();
    /** A wheel slower than this, mm/s, counts as stopped. */
    static final double MOVING_MM_S = 0.01;
    private static final Logger LOG = Logger.getLogger(Scout.class.getName());

    /**
     * The state vector of the C library ({@code long State[45]}; indices in {@link StateVector}),
     * refreshed by {@link #gs} and, in part, by {@link #get_sn}, {@link #get_bp}, {@link #get_rc} and
     * {@link #get_rv}; only the robot's own code writes it.
     */
    public final long[] State = new long[StateVector.NUM_STATE];

    private final Object lock = new Object();
    private final PoseFrame frame = new PoseFrame();
    private SonarSchedule sonars = new SonarSchedule(0);
    private long motionTimeoutMs;
    private long lastMotionMs = -1;
    private boolean refused;
    private long wallStartNanos = -1;
    private long simStartMs;

    /**
     * A Scout with the shipped parameters ({@code testLoadFiles/robots/scout.p}).
     *
     * @param name the robot's name in the world
     * @param host the Environment's host
     * @param port the Environment's robot port
     */
    public Scout(String name, String host, int port) {
        this(name, host, port, DEFAULT_PARAMETERS);
    }

    /**
     * @param name      the robot's name in the world
     * @param host      the Environment's host
     * @param port      the Environment's robot port
     * @param paramFile the robot's parameter file: a path, or a shipped name such as {@code scout}
     */
    public Scout(String name, String host, int port, String paramFile) {
        this(name, host, port, RobotParameterFiles.load(paramFile));
    }

    /**
     * @param name       the robot's name in the world
     * @param host       the Environment's host
     * @param port       the Environment's robot port
     * @param parameters the robot's parameters
     */
    public Scout(String name, String host, int port, RobotParameters parameters) {
        super(name, host, port, RobotKind.SCOUT.id(), parameters);
        Arrays.fill(State, StateVector.STATE_SONAR_0, StateVector.STATE_SONAR_15 + 1, NomadUnits.MAX_SONAR_INCHES);
    }

    // ---- connection ----

    /**
     * Connects to the Environment as the robot named in the constructor and waits (bounded) for its
     * welcome; the calling thread becomes the robot's code.
     *
     * @return true if connected; otherwise {@link #getConnectionError()} says why
     */
    public boolean connect_robot() {
        return tryConnect(HardwareOptions.defaults());
    }

    /** @return true if the robot was connected and has left the run */
    public boolean disconnect_robot() {
        if (!isConnected()) {
            return false;
        }
        disconnect();
        return true;
    }

    /** Starts the default sonar schedule (see {@link #conf_sn}) from the welcome's time. */
    @Override
    protected void welcomed(RobotState initial) {
        synchronized (lock) {
            sonars = new SonarSchedule(initial.timeMs());
        }
    }

    /**
     * Takes each step's state: runs the sonar firings due (see {@link #conf_sn}) and the motion
     * timeout (see {@link #conf_tm}). Runs on the hardware thread while the robot's code is yielded.
     */
    @Override
    protected void responded(RobotSensorResponse response) {
        super.responded(response);
        RobotState s = response.state();
        synchronized (lock) {
            if (wallStartNanos < 0) {
                wallStartNanos = System.nanoTime();
                simStartMs = s.timeMs();
            }
            sonars.observe(s.timeMs(), s.get(SonarReading.PART).ranges());
            refused |= !s.errors().isEmpty();
            if (motionTimeoutMs > 0 && lastMotionMs >= 0 && s.timeMs() - lastMotionMs >= motionTimeoutMs) {
                lastMotionMs = -1;
                LOG.fine(() -> "robot " + getName() + ": no motion command for " + motionTimeoutMs + " ms: stopping");
                request(new Command.Stop());
            }
        }
    }

    // ---- motion: none of these block ----

    /**
     * Velocity mode: each wheel turns at its velocity until the next motion command (or the motion
     * timeout, {@link #conf_tm}).
     *
     * @param right the right wheel's velocity, 1/10 inch/s
     * @param left  the left wheel's velocity, 1/10 inch/s
     * @param turret ignored: the Scout has no turret
     * @return true if sent
     */
    public boolean vm(int right, int left, int turret) {
        return motion(new Command.SetVel2(tenthInchToMm(left), tenthInchToMm(right)));
    }

    /**
     * Velocity mode by translation and steering, the C library's macro: right = trans + steer ·
     * {@value #ROTATION_CONSTANT}, left = trans − steer · {@value #ROTATION_CONSTANT}, each product
     * truncated towards zero in single precision, as {@code (int)((float)steer*ROTATION_CONSTANT)}.
     *
     * @param trans translational velocity, 1/10 inch/s
     * @param steer rotational velocity, 1/10 degree/s, counter-clockwise positive
     * @return true if sent
     */
    public boolean scout_vm(int trans, int steer) {
        int wheel = (int) ((float) steer * (float) ROTATION_CONSTANT);
        return vm(trans + wheel, trans - wheel, 0);
    }

    /**
     * Position relative: moves each wheel by a distance; both start and finish together, at the
     * speed set by {@link #sp}.
     *
     * @param right the right wheel's distance, 1/10 inch, negative backwards
     * @param left  the left wheel's distance, 1/10 inch
     * @param turret ignored: the Scout has no turret
     * @return true if sent
     */
    public boolean pr(int right, int left, int turret) {
        return motion(new Command.MoveWheels(tenthInchToMm(left), tenthInchToMm(right)));
    }

    /**
     * Sets the accelerations (and decelerations) of the motion commands.
     *
     * @param trans  translational acceleration, 1/10 inch/s², greater than 0
     * @param steer  rotational acceleration, 1/10 degree/s², greater than 0
     * @param turret ignored: the Scout has no turret
     * @return true if sent; false for an acceleration that is not positive
     */
    public boolean ac(int trans, int steer, int turret) {
        if (trans <= 0 || steer <= 0) {
            return false;
        }
        return send(new Command.SetAccel(tenthInchToMm(trans), tenthDegToDeg(steer)));
    }

    /**
     * Sets the speed limits (used by {@link #pr}, and capping {@link #vm}), within the parameter
     * file's maxima; does not move the robot.
     *
     * @param trans  translational speed, 1/10 inch/s, at least 0
     * @param steer  rotational speed, 1/10 degree/s, at least 0
     * @param turret ignored: the Scout has no turret
     * @return true if sent; false for a negative speed
     */
    public boolean sp(int trans, int steer, int turret) {
        if (trans < 0 || steer < 0) {
            return false;
        }
        return send(new Command.SetMaxTransVel(tenthInchToMm(trans)))
                && send(new Command.SetMaxRotVel(tenthDegToDeg(steer)));
    }

    /** @return true if sent: the robot stops at once and holds its position */
    public boolean st() {
        return halt();
    }

    /** @return true if sent: the motors go limp; in RoboSim the robot stops, as {@link #st} */
    public boolean lp() {
        return halt();
    }

    /**
     * Position absolute: not on a Scout.
     *
     * @param trans  ignored
     * @param steer  ignored
     * @param turret ignored
     * @return false, as on the real robot
     */
    public boolean pa(int trans, int steer, int turret) {
        return false;
    }

    /**
     * Waits, yielding in simulated time (at least one step, so that motion commands just made have
     * begun), until the named wheels have stopped.
     *
     * @param right   non-zero to wait for the right wheel (the translation axis)
     * @param left    non-zero to wait for the left wheel (the steering axis)
     * @param turret  ignored: the Scout has no turret
     * @param timeout the longest wait, simulated seconds; 0 or less waits without limit
     * @return true when the wheels have stopped; false on timeout or if the robot is disconnected
     */
    public boolean ws(int right, int left, int turret, int timeout) {
        if (!isConnected()) {
            return false;
        }
        long deadline = timeout > 0 ? state().timeMs() + timeout * 1000L : Long.MAX_VALUE;
        while (true) {
            sleepSimulated(1);
            if (!isConnected()) {
                return false;
            }
            long status = motorStatus(state());
            boolean stopped = (right == 0 || (status & StateVector.MOTOR_RIGHT) == 0)
                    && (left == 0 || (status & StateVector.MOTOR_LEFT) == 0);
            if (stopped) {
                return true;
            }
            if (state().timeMs() >= deadline) {
                return false;
            }
        }
    }

    /**
     * Sets the motion timeout: once {@code timeout} seconds of simulated time have passed since the
     * last {@link #vm}, {@link #scout_vm} or {@link #pr} (timed from the state it was made in),
     * the robot is stopped, checked as each step's state arrives; the stop goes out with that step's
     * requests, ahead of any the code then makes.
     *
     * @param timeout seconds, 0..255; 0 switches the timeout off
     * @return true if set; false for a timeout out of range
     */
    public boolean conf_tm(int timeout) {
        if (timeout < 0 || timeout > 255 || !isConnected()) {
            return false;
        }
        synchronized (lock) {
            motionTimeoutMs = timeout * 1000L;
        }
        return true;
    }

    // ---- pose ----

    /** @return true: the configuration (x, y, heading) reads 0, 0, 0 from this state on */
    public boolean zr() {
        return reframe((f, s) -> f.zero(s.x(), s.y(), s.th()));
    }

    /**
     * Defines the current position; the heading stays.
     *
     * @param x the position's x, 1/10 inch
     * @param y the position's y, 1/10 inch
     * @return true if defined
     */
    public boolean dp(int x, int y) {
        return reframe((f, s) -> f.definePosition(s.x(), s.y(), tenthInchToMm(x), tenthInchToMm(y)));
    }

    /**
     * Defines the current heading; the position stays.
     *
     * @param th     the heading, 1/10 degree, counter-clockwise
     * @param turret ignored: the Scout has no turret (its entry repeats the heading)
     * @return true if defined
     */
    public boolean da(int th, int turret) {
        return reframe((f, s) -> f.defineHeading(s.x(), s.y(), s.th(), tenthDegToDeg(th)));
    }

    // ---- sensors ----

    /**
     * Configures the sonars: from the latest state on, firings {@code rate · 4} ms apart, cycling
     * through {@code order}; a sonar's entry in {@link #State} changes only when it fires. The
     * schedule is emulated from the Environment's readings, exactly as {@link SonarSchedule} says:
     * firing k (k = 0, 1, ...) is of sonar {@code order[k mod n]} at {@code c + (k + 1) · rate · 4}
     * ms, {@code c} being the time of the state the call was made in, and takes the range of the
     * first state at or after it. An empty order switches the sonars off. The default is every
     * sonar, 0 to 15, at rate 1.
     *
     * @param rate  the firing period in 4 ms units, at least 1
     * @param order sonar numbers 0..15 in firing order, ended by 255 or after 16 entries
     * @return true if configured; false for a rate below 1 or an entry that is not a sonar
     */
    public boolean conf_sn(int rate, int[] order) {
        int[] sonarOrder = SonarSchedule.parseOrder(order);
        if (rate < 1 || sonarOrder == null || !isConnected()) {
            return false;
        }
        boolean on;
        synchronized (lock) {
            sonars.configure(rate, sonarOrder, state().timeMs());
            on = sonars.firesAny();
        }
        return send(new Command.SetSonar(on));
    }

    /**
     * Configures the infrared sensors: not on a Scout.
     *
     * @param history ignored
     * @param order   ignored
     * @return false, as on the real robot
     */
    public boolean conf_ir(int history, int[] order) {
        return false;
    }

    /**
     * Configures the compass: not on a Scout.
     *
     * @param mode ignored
     * @return false, as on the real robot
     */
    public boolean conf_cp(int mode) {
        return false;
    }

    /** @return true once the whole {@link #State} is refreshed from the next step's state */
    public boolean gs() {
        if (!awaitReply()) {
            return false;
        }
        RobotState s = state();
        Arrays.fill(State, StateVector.STATE_IR_0, StateVector.STATE_IR_15 + 1, 0);
        fillSonar();
        fillConf(s);
        fillVel(s);
        State[StateVector.STATE_BUMPER] = s.get(Bumpers.PART).sectors();
        State[StateVector.STATE_LASER] = 0;
        State[StateVector.STATE_COMPASS] = 0;
        synchronized (lock) {
            State[StateVector.STATE_ERROR] = refused ? 1 : 0;
            refused = false;
            long wallMs = wallStartNanos < 0 ? 0 : (System.nanoTime() - wallStartNanos) / 1_000_000;
            State[StateVector.STATE_SIM_SPEED] = wallMs <= 0 ? 0 : Math.round(10.0 * (s.timeMs() - simStartMs) / wallMs);
        }
        return true;
    }

    /** @return true once the sonar entries of {@link #State} are refreshed from the next step's state */
    public boolean get_sn() {
        if (!awaitReply()) {
            return false;
        }
        fillSonar();
        return true;
    }

    /** @return true once {@code State[STATE_BUMPER]} is refreshed from the next step's state */
    public boolean get_bp() {
        if (!awaitReply()) {
            return false;
        }
        State[StateVector.STATE_BUMPER] = state().get(Bumpers.PART).sectors();
        return true;
    }

    /** @return true once the configuration (x, y, heading, turret) is refreshed from the next step */
    public boolean get_rc() {
        if (!awaitReply()) {
            return false;
        }
        fillConf(state());
        return true;
    }

    /** @return true once the velocities and motor status are refreshed from the next step */
    public boolean get_rv() {
        if (!awaitReply()) {
            return false;
        }
        fillVel(state());
        return true;
    }

    /**
     * Talks: the viewer shows the text and the Environment logs it.
     *
     * @param text what to say, at most 1000 characters
     * @return true if sent
     */
    public boolean tk(String text) {
        if (text == null || !isConnected()) {
            return false;
        }
        say(text);
        return true;
    }

    /**
     * Reports one of the robot's figures for the run's results (RoboSim's own call; the Nomad
     * library has none): the Environment keeps the last value of each name for the run's report, and
     * recordings and viewers see each report. It is sent with the step's requests, as the motion
     * calls are. See {@link #reportMetric} for the rules.
     *
     * @param name  the figure's name: a letter, then up to 63 letters, digits, {@code _}, {@code .} or
     *              {@code -}, such as {@code cellsExplored}
     * @param value its value now, a finite number
     * @return true if sent; false if the robot is not connected, or the name or value breaks its rule
     *         (nothing is sent then, and the rule is logged)
     */
    public boolean report_metric(String name, double value) {
        Command.ReportMetric metric;
        try {
            metric = new Command.ReportMetric(name, value);
        } catch (IllegalArgumentException e) {
            LOG.warning(() -> "robot " + getName() + ": report_metric sent nothing: " + e.getMessage());
            return false;
        }
        return send(metric);
    }

    /**
     * Asks the Environment to end the run after this step (RoboSim's own call): the run's report
     * names this robot, the step and the reason; only the first request of a run counts. Keep the
     * robot in the run until it ends (a loop around {@link #gs} that runs until it returns false),
     * so that the request is sent. See {@link #endRun}.
     *
     * @param reason why, such as {@code gold found}: 1 to 200 characters, one line
     * @return true if sent; false if the robot is not connected, or the reason breaks its rule
     *         (nothing is sent then, and the rule is logged)
     */
    public boolean end_run(String reason) {
        Command.EndRun end;
        try {
            end = new Command.EndRun(reason);
        } catch (IllegalArgumentException e) {
            LOG.warning(() -> "robot " + getName() + ": end_run sent nothing: " + e.getMessage());
            return false;
        }
        return send(end);
    }

    // ---- helpers ----

    private boolean awaitReply() {
        if (!isConnected()) {
            return false;
        }
        sleepSimulated(1);
        return isConnected();
    }

    private boolean send(Command command) {
        if (!isConnected()) {
            return false;
        }
        request(command);
        return true;
    }

    private boolean motion(Command command) {
        if (!send(command)) {
            return false;
        }
        synchronized (lock) {
            lastMotionMs = state().timeMs();
        }
        return true;
    }

    private boolean reframe(BiConsumer<PoseFrame, RobotState> change) {
        if (!isConnected()) {
            return false;
        }
        RobotState s = state();
        synchronized (lock) {
            change.accept(frame, s);
        }
        return true;
    }

    private boolean halt() {
        if (!send(new Command.Stop())) {
            return false;
        }
        synchronized (lock) {
            lastMotionMs = -1;
        }
        return true;
    }

    private void fillSonar() {
        synchronized (lock) {
            for (int i = 0; i < StateVector.SONARS; i++) {
                State[StateVector.STATE_SONAR_0 + i] = sonars.inches(i);
            }
        }
    }

    private void fillConf(RobotState s) {
        double[] pose;
        synchronized (lock) {
            pose = frame.apply(s.x(), s.y(), s.th());
        }
        State[StateVector.STATE_CONF_X] = mmToTenthInch(pose[0]);
        State[StateVector.STATE_CONF_Y] = mmToTenthInch(pose[1]);
        State[StateVector.STATE_CONF_STEER] = headingToTenthDeg(pose[2]);
        State[StateVector.STATE_CONF_TURRET] = State[StateVector.STATE_CONF_STEER];
    }

    private void fillVel(RobotState s) {
        State[StateVector.STATE_VEL_RIGHT] = mmToTenthInch(s.rightVel());
        State[StateVector.STATE_VEL_LEFT] = mmToTenthInch(s.leftVel());
        State[StateVector.STATE_VEL_TURRET] = 0;
        State[StateVector.STATE_MOTOR_STATUS] = motorStatus(s);
    }

    private static long motorStatus(RobotState s) {
        return (Math.abs(s.rightVel()) > MOVING_MM_S ? StateVector.MOTOR_RIGHT : 0)
                | (Math.abs(s.leftVel()) > MOVING_MM_S ? StateVector.MOTOR_LEFT : 0);
    }
}
