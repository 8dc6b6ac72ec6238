package robosim.aria;


/**
 * ARIA's {@code ArRobotConnector}: connects an {@link ArRobot} where the command line says, so that
 * the same program reaches a RoboSim Environment in lockstep, RoboSim's Pioneer port, MobileSim or
 * a real Pioneer, as ARIA programs do.
 *
 * <p>Where, from the arguments its parser holds:
 * <ul>
 * <li>{@code NAME HOST PORT} first (RoboSim's own form, as {@code bin/robosim robot} and
 *     experiments start a program): the robot named NAME of the Environment at HOST:PORT, in
 *     lockstep;</li>
 * <li>else {@code -remoteHost}/{@code -rh HOST} and {@code -remoteRobotTcpPort}/{@code -rrtp PORT}
 *     (default 8101): the Pioneer robot server there (RoboSim's Pioneer port, MobileSim, a robot
 *     behind a serial-to-TCP bridge);</li>
 * <li>else the simulator on {@code localhost:8101}, as ARIA tries first. ARIA then falls back to a
 *     serial port ({@code -robotPort}/{@code -rp}, {@code -robotBaud}/{@code -rb}); a simulated
 *     robot has none, so the connection fails there, saying so.</li>
 * </ul>
 * As in ARIA, a Pioneer robot server's TCP port is tried when the robot is set up, and nobody
 * answering there fails the connection at once; a RoboSim Environment is waited for (within the
 * connect timeout), so that robots may start before it.
 * ARIA's logging flags ({@code -rlpr}, {@code -rlps}, {@code -rlmr}, {@code -rlms}, {@code -rlvr},
 * {@code -rla}) and {@code -ris}/{@code -rins} are taken and kept ({@link #getRemoteIsSim()}); the
 * lockstep link has no packets to log, so they log nothing more.
 */
public class ArRobotConnector {
    /** The host ARIA looks for a simulator on. */
    public static final String DEFAULT_HOST = "localhost";
    /** The TCP port ARIA looks for a robot server on: MobileSim's and the first Pioneer port's. */
    public static final int DEFAULT_PORT = 8101;

    private final ArArgumentParser parser;
    private ArRobot robot;
    private final boolean autoParseArgs;
    private boolean parsed;
    private String environmentName;
    private String environmentHost;
    private int environmentPort;
    private String remoteHost;
    private String robotPort = "/dev/ttyS0";
    private int remoteRobotTcpPort = DEFAULT_PORT;
    private int robotBaud = 9600;
    private boolean remoteIsSim;
    private boolean remoteIsNotSim;
    private boolean usingSim;
    private final boolean connectAllComponents;

    /**
     * @param parser the program's arguments; the connector takes its own when they are parsed
     * @param robot  the robot to connect
     */
    public ArRobotConnector(ArArgumentParser parser, ArRobot robot) {
        this(parser, robot, true, true);
    }

    /**
     * @param parser                the program's arguments
     * @param robot                 the robot to connect
     * @param autoParseArgs         whether {@link #connectRobot()} parses the arguments if
     *                              {@link Aria#parseArgs()} has not yet
     * @param connectAllComponents  ARIA's: connect the robot's separate boards (an MTX's battery,
     *                              sonar) in {@link #connectRobot()}; a simulated robot's come with it,
     *                              which {@link #connectRobot()} says as ARIA does
     */
    public ArRobotConnector(ArArgumentParser parser, ArRobot robot, boolean autoParseArgs,
                            boolean connectAllComponents) {
        this.parser = parser;
        this.robot = robot;
        this.autoParseArgs = autoParseArgs;
        this.connectAllComponents = connectAllComponents;
        Aria.addParseArgsCB(this::parseArgs, 75, "ArRobotConnector");
        Aria.addLogOptionsCB(this::logOptions, 90);
    }

    /**
     * @return the arguments parsed, as {@link #parseArgs(ArArgumentParser)} with this connector's
     *         parser; false without one, as ARIA's {@code ArRobotConnector::parseArgs()} answers for a
     *         connector made with a NULL parser (singleThreadLoopExample.cpp), which then connects where
     *         the defaults say
     */
    public boolean parseArgs() {
        return parser != null && parseArgs(parser);
    }

    /**
     * Takes the connector's arguments from the parser (once; later calls return true).
     *
     * @param from the arguments
     * @return false if one is given a bad value (logged)
     */
    public boolean parseArgs(ArArgumentParser from) {
        if (parsed) {
            return true;
        }
        parsed = true;
        takeEnvironment(from);
        remoteIsSim = from.checkArgument("-remoteIsSim") || from.checkArgument("-ris");
        remoteIsNotSim = from.checkArgument("-remoteIsNotSim") || from.checkArgument("-rins");
        for (String[] flag : new String[][] {{"-robotLogPacketsReceived", "-rlpr"}, {"-robotLogPacketsSent", "-rlps"},
                {"-robotLogMovementReceived", "-rlmr"}, {"-robotLogMovementSent", "-rlms"},
                {"-robotLogVelocitiesReceived", "-rlvr"}, {"-robotLogActions", "-rla"}}) {
            if (from.checkArgument(flag[0]) || from.checkArgument(flag[1])) {
                ArLog.log(ArLog.Verbose, "ArRobotConnector: %s: the lockstep link has no packets to log", flag[0]);
            }
        }
        String[] host = {remoteHost};
        String[] serial = {robotPort};
        int[] port = {remoteRobotTcpPort};
        int[] baud = {robotBaud};
        boolean ok = from.checkParameterArgumentString("-remoteHost", host)
                && from.checkParameterArgumentString("-rh", host)
                && from.checkParameterArgumentString("-robotPort", serial)
                && from.checkParameterArgumentString("-rp", serial)
                && from.checkParameterArgumentInteger("-remoteRobotTcpPort", port)
                && from.checkParameterArgumentInteger("-rrtp", port)
                && from.checkParameterArgumentInteger("-robotBaud", baud)
                && from.checkParameterArgumentInteger("-rb", baud);
        remoteHost = host[0];
        robotPort = serial[0];
        remoteRobotTcpPort = port[0];
        robotBaud = baud[0];
        if (ok && (remoteRobotTcpPort < 1 || remoteRobotTcpPort > 65535)) {
            ArLog.log(ArLog.Terse, "ArRobotConnector: %d was supplied for -remoteRobotTcpPort: a port is 1 to 65535",
                    remoteRobotTcpPort);
            ok = false;
        }
        return ok;
    }

    /** Takes RoboSim's {@code NAME HOST PORT}, when the arguments begin with them. */
    private void takeEnvironment(ArArgumentParser from) {
        String name = from.getArg(1);
        String host = from.getArg(2);
        String port = from.getArg(3);
        if (name == null || host == null || port == null || name.startsWith("-") || host.startsWith("-")
                || !port.matches("\\d{1,5}")) {
            return;
        }
        int p = Integer.parseInt(port);
        if (p < 1 || p > 65535) {
            return;
        }
        environmentName = name;
        environmentHost = host;
        environmentPort = p;
        for (int i = 0; i < 3; i++) {
            from.removeArg(1);
        }
    }

    /** Logs the connector's options, as ARIA's does (with RoboSim's own form first). */
    public void logOptions() {
        ArLog.log(ArLog.Terse, "Options for ArRobotConnector (see docs for more details):");
        ArLog.log(ArLog.Terse, "");
        ArLog.log(ArLog.Terse, "RoboSim Environment (lockstep), given first:");
        ArLog.log(ArLog.Terse, "NAME HOST PORT");
        ArLog.log(ArLog.Terse, "Robot options:");
        for (String line : new String[] {"-remoteHost <remoteHostNameOrIP>", "-rh <remoteHostNameOrIP>",
                "-robotPort <robotSerialPort>", "-rp <robotSerialPort>", "-robotBaud <baud>", "-rb <baud>",
                "-remoteRobotTcpPort <remoteRobotTcpPort>", "-rrtp <remoteRobotTcpPort>", "-remoteIsSim", "-ris",
                "-remoteIsNotSim", "-rins", "-robotLogPacketsReceived", "-rlpr", "-robotLogPacketsSent", "-rlps",
                "-robotLogMovementReceived", "-rlmr", "-robotLogMovementSent", "-rlms", "-robotLogVelocitiesReceived",
                "-rlvr", "-robotLogActions", "-rla"}) {
            ArLog.log(ArLog.Terse, line);
        }
    }

    /** @return whether the robot was told where to connect, as {@link #setupRobot(ArRobot)} */
    public boolean setupRobot() {
        return setupRobot(robot);
    }

    /**
     * Tells the robot where it connects, from the arguments (parsed first if they were not and the
     * connector parses them itself).
     *
     * @param which the robot; the connector's own when it was given none
     * @return false if there is no robot, or the arguments are bad
     */
    public boolean setupRobot(ArRobot which) {
        if (robot == null) {
            robot = which;
        }
        if (which == null) {
            ArLog.log(ArLog.Normal, "ArRobotConnector::setupRobot: NULL robot, cannot setup robot");
            return false;
        }
        if (autoParseArgs && parser != null && !parseArgs()) {
            return false;
        }
        if (!autoParseArgs && !parsed) {
            ArLog.log(ArLog.Normal, "ArRobotConnector: Args not parsed and are not autoparsed, so connection may fail"
                    + " and command line arguments won't be used");
        }
        if (which.isConnected()) {
            ArLog.log(ArLog.Normal, "ArRobotConnector::setupRobot: robot already has device connection, will not setup"
                    + " robot");
            return true;
        }
        if (environmentName != null) {
            ArLog.log(ArLog.Normal, "Connecting robot %s to the RoboSim Environment at %s:%d", environmentName,
                    environmentHost, environmentPort);
            which.relocate(environmentName, environmentHost, environmentPort, which.getParameters());
            usingSim = true;
            return true;
        }
        String host = remoteHost != null ? remoteHost : DEFAULT_HOST;
        ArLog.log(ArLog.Normal, "Connnecting to robot using TCP connection to %s:%d...", host, remoteRobotTcpPort);
        if (!new ArTcpConnection().openSimple(host, remoteRobotTcpPort)) {
            // ARIA opens the TCP connection here, and gives up at once when nobody answers
            if (remoteHost != null) {
                ArLog.log(ArLog.Terse, "Could not connect robot to remote host %s, port %d.", remoteHost,
                        remoteRobotTcpPort);
            } else {
                ArLog.log(ArLog.Normal, "Could not connect to simulator, connecting to robot through serial port %s.",
                        robotPort);
                ArLog.log(ArLog.Terse, "ArRobotConnector: a simulated robot has no serial port: start RoboSim's"
                        + " Pioneer port on %s:%d, or give -remoteHost HOST (a Pioneer robot server) or NAME HOST"
                        + " PORT first (a RoboSim Environment)", DEFAULT_HOST, remoteRobotTcpPort);
            }
            return false;
        }
        if (remoteHost != null) {
            ArLog.log(ArLog.Normal, "Connected to remote host %s through tcp.\n", remoteHost);
        } else {
            ArLog.log(ArLog.Normal, "Connecting to simulator through tcp.\n");
        }
        which.usePioneerServer(which.getName(), host, remoteRobotTcpPort);
        usingSim = remoteHost == null || (remoteIsSim && !remoteIsNotSim);
        return true;
    }

    /**
     * Connects the connector's robot, as {@link #connectRobot(ArRobot)}; then, as ARIA's {@code
     * ArRobotConnector::connectRobot()} (ArRobotConnector.cpp), when all components are to be
     * connected and the robot is a simulator's ({@link #getRemoteIsSim()}), says that there are none
     * to connect.
     *
     * @return whether the robot connected
     */
    public boolean connectRobot() {
        if (!connectRobot(robot)) {
            return false;
        }
        if (connectAllComponents && getRemoteIsSim()) {
            ArLog.log(ArLog.Normal,
                    "ArRobotConnector: Connected to simulator, not connecting to additional hardware components.");
        }
        return true;
    }

    /**
     * Sets the robot up ({@link #setupRobot(ArRobot)}) and connects it, waiting (bounded) for the
     * connection; a robot connected is one {@link Aria#exit} disconnects.
     *
     * @param which the robot
     * @return whether it connected; if not, why is logged
     */
    public boolean connectRobot(ArRobot which) {
        if (!setupRobot(which)) {
            return false;
        }
        if (which.isConnected()) {
            return true;
        }
        which.logConnectionAsAria();
        if (!which.blockingConnect()) {
            ArLog.log(ArLog.Terse, "ArRobotConnector: could not connect robot %s: %s", which.getName(),
                    which.getConnectionError());
            return false;
        }
        Aria.addRobot(which);
        return true;
    }

    /** @return whether the robot connected through this connector was disconnected */
    public boolean disconnectAll() {
        return robot != null && robot.disconnect();
    }

    /** @return the robot */
    public ArRobot getRobot() {
        return robot;
    }

    /** @return the Pioneer robot server's host given ({@code -remoteHost}), or null */
    public String getRemoteHost() {
        return remoteHost;
    }

    /** @return the Pioneer robot server's port ({@code -remoteRobotTcpPort}, default 8101) */
    public int getRemoteRobotTcpPort() {
        return remoteRobotTcpPort;
    }

    /**
     * Whether the robot is a simulator's, as ARIA's {@code ArRobotConnector::getRemoteIsSim}
     * (ArRobotConnector.cpp) decides: {@code -remoteIsSim} says yes, {@code -remoteIsNotSim} no;
     * otherwise a robot whose serial number is {@code SIM} is one (every robot RoboSim connects, in
     * lockstep or through a Pioneer port, as MobileSim's robots).
     *
     * @return whether the robot is simulated
     */
    public boolean getRemoteIsSim() {
        if (remoteIsSim) {
            return true;
        }
        if (remoteIsNotSim) {
            return false;
        }
        return robot != null && "SIM".equalsIgnoreCase(robot.getRobotSerialNumber());
    }

    /** @return whether {@code -remoteIsNotSim} was given */
    public boolean getRemoteIsNotSim() {
        return remoteIsNotSim;
    }

    /** @return whether the robot is a simulated one: always, in RoboSim, once set up (ARIA's {@code isUsingSim}) */
    public boolean getUsingSim() {
        return usingSim;
    }

    /** @return the robot's name in the RoboSim Environment given first on the command line, or null */
    public String getEnvironmentRobotName() {
        return environmentName;
    }
}
