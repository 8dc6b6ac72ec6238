package robosim.scout;

/**
 * The Nomad client library's global functions, for a program that drives one Scout as the C
 * library did: {@code connect_robot}, then calls on that robot, with the state vector in the
 * global {@link #State}. Each call does what the {@link Scout} call of the same name does, then
 * copies that robot's state vector into {@link #State}. Every call returns false while no robot is
 * connected.
 *
 * <pre>{@code
 * import static robosim.scout.Nomad.*;
 * import static robosim.scout.StateVector.*;
 *
 * if (!connect_robot(args[0], args[1], Integer.parseInt(args[2]))) return;
 * while (gs() && State[STATE_SONAR_0] > 30) {
 *     scout_vm(100, 0);        // 10 inches/s straight ahead
 * }
 * st();
 * disconnect_robot(args[0]);
 * }</pre>
 *
 * <p>One robot per program (per JVM), as the C library: to run several Scouts as threads of one
 * JVM, give each thread a {@link Scout} of its own.
 */
public final class Nomad {
    /** The state vector of the connected robot, as of the last call (indices in {@link StateVector}). */
    public static final long[] State = new long[StateVector.NUM_STATE];

    private static volatile Scout robot;
    private static volatile String connectionError;

    private Nomad() {
    }

    /**
     * Connects to the robot whose world name is the number {@code id} (a world may name a robot
     * {@code "1"}).
     *
     * @param id   the robot's number
     * @param host the Environment's host
     * @param port the Environment's robot port
     * @return true if connected
     */
    public static boolean connect_robot(long id, String host, int port) {
        return connect_robot(Long.toString(id), host, port);
    }

    /**
     * Connects to a robot with the shipped Scout parameters; the calling thread becomes its code.
     *
     * @param name the robot's name in the world
     * @param host the Environment's host
     * @param port the Environment's robot port
     * @return true if connected; false if a robot is already connected or connecting failed (then
     *         {@link #connectionError()} says why)
     */
    public static synchronized boolean connect_robot(String name, String host, int port) {
        if (robot != null && robot.isConnected()) {
            connectionError = "robot " + robot.getName() + " is connected: one robot per program";
            return false;
        }
        Scout s = new Scout(name, host, port);
        if (!s.connect_robot()) {
            connectionError = s.getConnectionError();
            return false;
        }
        robot = s;
        return copy(s, true);
    }

    /**
     * @param id the connected robot's number
     * @return true if it was connected and has left the run
     */
    public static boolean disconnect_robot(long id) {
        return disconnect_robot(Long.toString(id));
    }

    /**
     * @param name the connected robot's name
     * @return true if it was connected and has left the run
     */
    public static synchronized boolean disconnect_robot(String name) {
        Scout s = robot;
        if (s == null || !s.getName().equals(name)) {
            return false;
        }
        robot = null;
        return s.disconnect_robot();
    }

    /** @return the connected robot, or null */
    public static Scout robot() {
        return robot;
    }

    /** @return why the last {@code connect_robot} failed, or null */
    public static String connectionError() {
        return connectionError;
    }

    /** @return see {@link Scout#gs} */
    public static boolean gs() {
        Scout s = robot;
        return s != null && copy(s, s.gs());
    }

    /** @return see {@link Scout#get_sn} */
    public static boolean get_sn() {
        Scout s = robot;
        return s != null && copy(s, s.get_sn());
    }

    /** @return see {@link Scout#get_bp} */
    public static boolean get_bp() {
        Scout s = robot;
        return s != null && copy(s, s.get_bp());
    }

    /** @return see {@link Scout#get_rc} */
    public static boolean get_rc() {
        Scout s = robot;
        return s != null && copy(s, s.get_rc());
    }

    /** @return see {@link Scout#get_rv} */
    public static boolean get_rv() {
        Scout s = robot;
        return s != null && copy(s, s.get_rv());
    }

    /**
     * @param right  the right wheel's velocity, 1/10 inch/s
     * @param left   the left wheel's velocity, 1/10 inch/s
     * @param turret ignored
     * @return see {@link Scout#vm}
     */
    public static boolean vm(int right, int left, int turret) {
        Scout s = robot;
        return s != null && s.vm(right, left, turret);
    }

    /**
     * @param trans translational velocity, 1/10 inch/s
     * @param steer rotational velocity, 1/10 degree/s
     * @return see {@link Scout#scout_vm}
     */
    public static boolean scout_vm(int trans, int steer) {
        Scout s = robot;
        return s != null && s.scout_vm(trans, steer);
    }

    /**
     * @param right  the right wheel's distance, 1/10 inch
     * @param left   the left wheel's distance, 1/10 inch
     * @param turret ignored
     * @return see {@link Scout#pr}
     */
    public static boolean pr(int right, int left, int turret) {
        Scout s = robot;
        return s != null && s.pr(right, left, turret);
    }

    /**
     * @param trans  1/10 inch/s²
     * @param steer  1/10 degree/s²
     * @param turret ignored
     * @return see {@link Scout#ac}
     */
    public static boolean ac(int trans, int steer, int turret) {
        Scout s = robot;
        return s != null && s.ac(trans, steer, turret);
    }

    /**
     * @param trans  1/10 inch/s
     * @param steer  1/10 degree/s
     * @param turret ignored
     * @return see {@link Scout#sp}
     */
    public static boolean sp(int trans, int steer, int turret) {
        Scout s = robot;
        return s != null && s.sp(trans, steer, turret);
    }

    /** @return see {@link Scout#st} */
    public static boolean st() {
        Scout s = robot;
        return s != null && s.st();
    }

    /** @return see {@link Scout#lp} */
    public static boolean lp() {
        Scout s = robot;
        return s != null && s.lp();
    }

    /**
     * @param trans  ignored
     * @param steer  ignored
     * @param turret ignored
     * @return false: not on a Scout
     */
    public static boolean pa(int trans, int steer, int turret) {
        return false;
    }

    /**
     * @param right   non-zero to wait for the right wheel
     * @param left    non-zero to wait for the left wheel
     * @param turret  ignored
     * @param timeout simulated seconds; 0 or less without limit
     * @return see {@link Scout#ws}
     */
    public static boolean ws(int right, int left, int turret, int timeout) {
        Scout s = robot;
        return s != null && s.ws(right, left, turret, timeout);
    }

    /**
     * @param timeout seconds, 0..255; 0 switches it off
     * @return see {@link Scout#conf_tm}
     */
    public static boolean conf_tm(int timeout) {
        Scout s = robot;
        return s != null && s.conf_tm(timeout);
    }

    /** @return see {@link Scout#zr} */
    public static boolean zr() {
        Scout s = robot;
        return s != null && s.zr();
    }

    /**
     * @param x 1/10 inch
     * @param y 1/10 inch
     * @return see {@link Scout#dp}
     */
    public static boolean dp(int x, int y) {
        Scout s = robot;
        return s != null && s.dp(x, y);
    }

    /**
     * @param th     1/10 degree
     * @param turret ignored
     * @return see {@link Scout#da}
     */
    public static boolean da(int th, int turret) {
        Scout s = robot;
        return s != null && s.da(th, turret);
    }

    /**
     * @param rate  firing period, 4 ms units
     * @param order sonar numbers, ended by 255
     * @return see {@link Scout#conf_sn}
     */
    public static boolean conf_sn(int rate, int[] order) {
        Scout s = robot;
        return s != null && s.conf_sn(rate, order);
    }

    /**
     * @param history ignored
     * @param order   ignored
     * @return false: not on a Scout
     */
    public static boolean conf_ir(int history, int[] order) {
        return false;
    }

    /**
     * @param mode ignored
     * @return false: not on a Scout
     */
    public static boolean conf_cp(int mode) {
        return false;
    }

    /**
     * @param text what to say
     * @return see {@link Scout#tk}
     */
    public static boolean tk(String text) {
        Scout s = robot;
        return s != null && s.tk(text);
    }

    /**
     * @param name  the figure's name
     * @param value its value now
     * @return see {@link Scout#report_metric}
     */
    public static boolean report_metric(String name, double value) {
        Scout s = robot;
        return s != null && s.report_metric(name, value);
    }

    /**
     * @param reason why the run should end
     * @return see {@link Scout#end_run}
     */
    public static boolean end_run(String reason) {
        Scout s = robot;
        return s != null && s.end_run(reason);
    }

    private static boolean copy(Scout s, boolean ok) {
        System.arraycopy(s.State, 0, State, 0, StateVector.NUM_STATE);
        return ok;
    }
}
