package robosim.aria;

import java.util.Map;
import java.util.TreeMap;

/**
 * ARIA's {@code ArLaserConnector}: makes, sets up and connects a robot's lasers from its parameter
 * file and the command line, as ArLaserConnector.cpp does.
 *
 * <p>RoboSim simulates one laser per robot, a SICK LMS200 ({@link ArLMS2xx}) mounted where the
 * robot's parameter file says ({@code LaserX/LaserY/LaserTh}): it is laser 1, of type
 * {@code lms2xx}, and it connects when the command line says {@code -connectLaser} (ARIA's
 * {@code LaserAutoConnect} is false for a Pioneer). Its settings come from ARIA's laser arguments:
 * {@code -laserDegrees}/{@code -ld 180|100}, {@code -laserIncrement}/{@code -li one|half},
 * {@code -laserUnits}/{@code -lu 1mm|1cm|10cm}, {@code -laserReflectorBits}/{@code -lrb
 * 1ref|2ref|3ref}, {@code -laserFlipped}/{@code -lf true|false}, {@code -laserMaxRange}/{@code -lmr
 * MM}, {@code -laserAdditionalIgnoreReadings}/{@code -lair LIST}, {@code -laserStartingBaud}/{@code
 * -lsb}, {@code -laserAutoBaud}/{@code -lab}. The port arguments ({@code -laserPort}, {@code
 * -laserPortType}, {@code -remoteLaserTcpPort}) are taken and kept: the simulated laser comes over
 * the robot's own link. Another type, or a second laser, is refused with the reason.
 *
 * <p>The laser's scans come over the robot's link: the Environment's, or a Pioneer port's (in the
 * laser packets of the simulator's laser, as MobileSim sends them).
 */
public class ArLaserConnector {
    /** The one laser type RoboSim simulates. */
    public static final String LMS2XX = "lms2xx";
    /** The most lasers a robot's arguments may name, as ARIA's default {@code Aria::getMaxNumLasers}. */
    public static final int MAX_LASERS = 2;

    /** A laser's settings from the command line, applied when it is set up. */
    private static final class LaserData {
        final int number;
        ArLaser laser;
        boolean connect;
        String degrees;
        String increment;
        String units;
        String reflectorBits;
        String startingBaud;
        String autoBaud;
        String ignore;
        Boolean flipped;
        Double maxRange;
        String port;
        String portType;
        Integer remoteTcpPort;

        LaserData(int number, ArLaser laser) {
            this.number = number;
            this.laser = laser;
        }
    }

    private final ArArgumentParser parser;
    private final ArRobot robot;
    private final boolean autoParseArgs;
    private final ArLog.LogLevel infoLogLevel;
    private final Map<Integer, LaserData> lasers = new TreeMap<>();
    private boolean parsed;

    /**
     * @param parser         the program's arguments
     * @param robot          the robot whose lasers these are
     * @param robotConnector the robot's connector (ARIA's; kept for the same call)
     */
    public ArLaserConnector(ArArgumentParser parser, ArRobot robot, ArRobotConnector robotConnector) {
        this(parser, robot, robotConnector, true, ArLog.Verbose);
    }

    /**
     * @param parser         the program's arguments
     * @param robot          the robot
     * @param robotConnector the robot's connector
     * @param autoParseArgs  whether {@link #connectLasers()} parses the arguments if nobody has
     * @param infoLogLevel   the level it logs what it does at
     */
    public ArLaserConnector(ArArgumentParser parser, ArRobot robot, ArRobotConnector robotConnector,
                            boolean autoParseArgs, ArLog.LogLevel infoLogLevel) {
        this.parser = parser;
        this.robot = robot;
        this.autoParseArgs = autoParseArgs;
        this.infoLogLevel = infoLogLevel;
        Aria.addParseArgsCB(this::parseArgs, 60, "ArLaserConnector");
        Aria.addLogOptionsCB(this::logOptions, 80);
    }

    /** @return as {@link #parseArgs(ArArgumentParser)} with the connector's parser */
    public boolean parseArgs() {
        return parseArgs(parser);
    }

    /**
     * Takes the lasers' arguments (once; later calls return true): the types given, then the laser
     * the robot's parameter file gives, then each laser's settings.
     *
     * @param from the arguments
     * @return false at a bad type or value (logged)
     */
    public boolean parseArgs(ArArgumentParser from) {
        if (parsed) {
            return true;
        }
        parsed = true;
        for (int n = 1; n <= MAX_LASERS; n++) {
            String suffix = suffix(n);
            String[] type = {null};
            if (!from.checkParameterArgumentString("-laserType" + suffix, type)
                    || !from.checkParameterArgumentString("-lt" + suffix, type)) {
                ArLog.log(ArLog.Normal, "ArLaserConnector: Bad laser type given for laser number %d", n);
                return false;
            }
            if (type[0] == null) {
                continue;
            }
            ArLaser made = create(type[0], n);
            if (made == null) {
                return false;
            }
            lasers.put(n, new LaserData(n, made));
            ArLog.log(infoLogLevel, "ArLaserConnector: Created %s as laser %d from arguments", made.getName(), n);
        }
        if (robot != null && !lasers.containsKey(1)) {
            ArLMS2xx fromParams = new ArLMS2xx(1);
            lasers.put(1, new LaserData(1, fromParams));
            ArLog.log(infoLogLevel, "ArLaserConnector: Created %s as laser 1 from parameter file", fromParams.getName());
        }
        for (LaserData d : lasers.values()) {
            if (!parseLaserArgs(from, d)) {
                return false;
            }
        }
        return true;
    }

    private static String suffix(int n) {
        return n == 1 ? "" : Integer.toString(n);
    }

    /** The laser a type names, or null (logged): RoboSim simulates one, laser 1, an LMS2xx. */
    private static ArLaser create(String type, int number) {
        if (!type.equalsIgnoreCase(LMS2XX)) {
            ArLog.log(ArLog.Normal, "Unknown laser type %s for laser %d, choices are %s", type, number, LMS2XX);
            return null;
        }
        if (number != 1) {
            ArLog.log(ArLog.Normal, "ArLaserConnector: laser %d: RoboSim simulates one laser per robot, laser 1, where"
                    + " its parameter file mounts it", number);
            return null;
        }
        return new ArLMS2xx(number);
    }

    private boolean parseLaserArgs(ArArgumentParser from, LaserData d) {
        String s = suffix(d.number);
        if (from.checkArgument("-connectLaser" + s) || from.checkArgument("-cl" + s)) {
            d.connect = true;
        }
        if (from.checkArgument("-doNotConnectLaser" + s) || from.checkArgument("-dncl" + s)) {
            d.connect = false;
        }
        String[] port = {d.port};
        String[] portType = {d.portType};
        int[] tcp = {d.remoteTcpPort == null ? 0 : d.remoteTcpPort};
        boolean[] flipped = {d.flipped != null && d.flipped};
        boolean[] flippedSet = {false};
        double[] maxRange = {d.maxRange == null ? 0 : d.maxRange};
        boolean[] maxRangeSet = {false};
        String[] degrees = {d.degrees};
        String[] increment = {d.increment};
        String[] units = {d.units};
        String[] bits = {d.reflectorBits};
        String[] startingBaud = {d.startingBaud};
        String[] autoBaud = {d.autoBaud};
        String[] ignore = {d.ignore};
        boolean ok = from.checkParameterArgumentString("-laserPort" + s, port)
                && from.checkParameterArgumentString("-lp" + s, port)
                && from.checkParameterArgumentString("-laserPortType" + s, portType)
                && from.checkParameterArgumentString("-lpt" + s, portType)
                && from.checkParameterArgumentInteger("-remoteLaserTcpPort" + s, tcp)
                && from.checkParameterArgumentInteger("-rltp" + s, tcp)
                && from.checkParameterArgumentBool("-laserFlipped" + s, flipped, flippedSet, false)
                && from.checkParameterArgumentBool("-lf" + s, flipped, flippedSet, false)
                && from.checkParameterArgumentDouble("-laserMaxRange" + s, maxRange, maxRangeSet, false)
                && from.checkParameterArgumentDouble("-lmr" + s, maxRange, maxRangeSet, false)
                && from.checkParameterArgumentString("-laserDegrees" + s, degrees)
                && from.checkParameterArgumentString("-ld" + s, degrees)
                && from.checkParameterArgumentString("-laserIncrement" + s, increment)
                && from.checkParameterArgumentString("-li" + s, increment)
                && from.checkParameterArgumentString("-laserUnits" + s, units)
                && from.checkParameterArgumentString("-lu" + s, units)
                && from.checkParameterArgumentString("-laserReflectorBits" + s, bits)
                && from.checkParameterArgumentString("-lrb" + s, bits)
                && from.checkParameterArgumentString("-laserStartingBaud" + s, startingBaud)
                && from.checkParameterArgumentString("-lsb" + s, startingBaud)
                && from.checkParameterArgumentString("-laserAutoBaud" + s, autoBaud)
                && from.checkParameterArgumentString("-lab" + s, autoBaud)
                && from.checkParameterArgumentString("-laserAdditionalIgnoreReadings" + s, ignore)
                && from.checkParameterArgumentString("-lair" + s, ignore);
        if (!ok) {
            ArLog.log(ArLog.Normal, "ArLaserConnector: Bad argument for laser %d (%s)", d.number, d.laser.getName());
            return false;
        }
        d.port = port[0];
        d.portType = portType[0];
        d.remoteTcpPort = tcp[0];
        if (flippedSet[0]) {
            d.flipped = flipped[0];
        }
        if (maxRangeSet[0]) {
            d.maxRange = maxRange[0];
        }
        d.degrees = degrees[0];
        d.increment = increment[0];
        d.units = units[0];
        d.reflectorBits = bits[0];
        d.startingBaud = startingBaud[0];
        d.autoBaud = autoBaud[0];
        d.ignore = ignore[0];
        return true;
    }

    /** Logs the laser options, as ARIA's connector does for each laser. */
    public void logOptions() {
        ArLog.log(ArLog.Terse, "Options for ArLaserConnector:");
        for (int n = 1; n <= MAX_LASERS; n++) {
            String s = suffix(n);
            ArLog.log(ArLog.Terse, "");
            ArLog.log(ArLog.Terse, "Laser%s options:", n == 1 ? "" : " " + n);
            ArLog.log(ArLog.Terse, "-laserType%s <%s>", s, LMS2XX);
            ArLog.log(ArLog.Terse, "-lt%s <%s>", s, LMS2XX);
            ArLog.log(ArLog.Terse, "-connectLaser%s", s);
            ArLog.log(ArLog.Terse, "-cl%s", s);
            LaserData d = lasers.get(n);
            ArLaser laser = d != null ? d.laser : n == 1 ? new ArLMS2xx(1) : null;
            if (laser == null) {
                continue;
            }
            for (String line : new String[] {"-laserPort%s <laserPort>", "-lp%s <laserPort>",
                    "-laserPortType%s <serial|tcp>", "-lpt%s <serial|tcp>",
                    "-remoteLaserTcpPort%s <remoteLaserTcpPort>", "-rltp%s <remoteLaserTcpPort>",
                    "-laserFlipped%s <true|false>", "-lf%s <true|false>", "-laserMaxRange%s <maxRange>",
                    "-lmr%s <maxRange>"}) {
                ArLog.log(ArLog.Terse, line, s);
            }
            ArLog.log(ArLog.Terse, "-laserDegrees%s <%s>", s, laser.getDegreesChoicesString());
            ArLog.log(ArLog.Terse, "-ld%s <%s>", s, laser.getDegreesChoicesString());
            ArLog.log(ArLog.Terse, "-laserIncrement%s <%s>", s, laser.getIncrementChoicesString());
            ArLog.log(ArLog.Terse, "-li%s <%s>", s, laser.getIncrementChoicesString());
            ArLog.log(ArLog.Terse, "-laserUnits%s <%s>", s, laser.getUnitsChoicesString());
            ArLog.log(ArLog.Terse, "-lu%s <%s>", s, laser.getUnitsChoicesString());
            ArLog.log(ArLog.Terse, "-laserReflectorBits%s <%s>", s, laser.getReflectorBitsChoicesString());
            ArLog.log(ArLog.Terse, "-lrb%s <%s>", s, laser.getReflectorBitsChoicesString());
            ArLog.log(ArLog.Terse, "-laserStartingBaud%s <%s>", s, laser.getStartingBaudChoicesString());
            ArLog.log(ArLog.Terse, "-lsb%s <%s>", s, laser.getStartingBaudChoicesString());
            ArLog.log(ArLog.Terse, "-laserAutoBaud%s <%s>", s, laser.getAutoBaudChoicesString());
            ArLog.log(ArLog.Terse, "-lab%s <%s>", s, laser.getAutoBaudChoicesString());
            ArLog.log(ArLog.Terse, "-laserAdditionalIgnoreReadings%s <readings>", s);
            ArLog.log(ArLog.Terse, "-lair%s <readings>", s);
        }
    }

    /**
     * Gives a laser of the program's own the number's settings from the command line.
     *
     * @param laser  the laser
     * @param number its number
     * @return false if a setting is refused (logged)
     */
    public boolean setupLaser(ArLaser laser, int number) {
        if (autoParseArgs && !parseArgs()) {
            return false;
        }
        LaserData d = lasers.computeIfAbsent(number, n -> new LaserData(n, laser));
        d.laser = laser;
        return apply(d);
    }

    /** @param laser a laser, as laser 1 @return false if a setting is refused (logged) */
    public boolean setupLaser(ArLaser laser) {
        return setupLaser(laser, 1);
    }

    private boolean apply(LaserData d) {
        ArLaser l = d.laser;
        boolean ok = (d.degrees == null || l.chooseDegrees(d.degrees))
                && (d.increment == null || l.chooseIncrement(d.increment))
                && (d.units == null || l.chooseUnits(d.units))
                && (d.reflectorBits == null || l.chooseReflectorBits(d.reflectorBits))
                && (d.startingBaud == null || l.chooseStartingBaud(d.startingBaud))
                && (d.autoBaud == null || l.chooseAutoBaud(d.autoBaud))
                && (d.ignore == null || l.addIgnoreReadings(d.ignore));
        if (ok && d.flipped != null) {
            l.setFlipped(d.flipped);
        }
        if (ok && d.maxRange != null) {
            if (!(d.maxRange > 0)) {
                ArLog.log(ArLog.Terse, "ArLaserConnector: %g was supplied for -laserMaxRange: it must be above 0",
                        d.maxRange);
                return false;
            }
            l.setMaxRange(d.maxRange);
        }
        return ok;
    }

    /**
     * Sets up a laser and connects it: added to the robot as its number, then switched on.
     *
     * @param laser  the laser
     * @param number its number
     * @return whether it connected (why not is logged)
     */
    public boolean connectLaser(ArLaser laser, int number) {
        if (!setupLaser(laser, number)) {
            return false;
        }
        if (robot == null) {
            ArLog.log(ArLog.Terse, "ArLaserConnector: no robot to connect %s to", laser.getName());
            return false;
        }
        if (!robot.addLaser(laser, number)) {
            return false;
        }
        ArLog.log(infoLogLevel, "ArLaserConnector: Connecting to laser %d (%s)", number, laser.getName());
        return laser.blockingConnect();
    }

    /** @return as {@link #connectLasers(boolean, boolean, boolean)} with ARIA's defaults (stop at a failure, add what connects) */
    public boolean connectLasers() {
        return connectLasers(false, true, false);
    }

    /**
     * Connects every laser whose arguments say {@code -connectLaser}.
     *
     * @param continueOnFailedConnect   go on to the next laser when one fails
     * @param addConnectedLasersToRobot add each laser that connects to the robot (always: a simulated
     *                                  laser reads the robot's scans only when it is the robot's)
     * @param addAllLasersToRobot       add every laser to the robot, connected or not
     * @return false if a laser failed to connect (logged), or the arguments are bad
     */
    public boolean connectLasers(boolean continueOnFailedConnect, boolean addConnectedLasersToRobot,
                                 boolean addAllLasersToRobot) {
        ArLog.log(infoLogLevel, "ArLaserConnector: Connecting lasers");
        if (autoParseArgs && !parsed) {
            ArLog.log(ArLog.Normal, "ArLaserConnector: Auto parsing args for lasers");
            if (!parseArgs()) {
                return false;
            }
        }
        if (robot == null) {
            ArLog.log(ArLog.Normal, "ArLaserConnector::connectLasers: there is no robot");
            return false;
        }
        boolean all = true;
        for (LaserData d : lasers.values()) {
            if (addAllLasersToRobot) {
                robot.addLaser(d.laser, d.number);
            }
            if (!d.connect) {
                continue;
            }
            if (!connectLaser(d.laser, d.number)) {
                ArLog.log(ArLog.Normal, "ArLaserConnector::connectLasers: Could not connect %s (laser %d)%s",
                        d.laser.getName(), d.number, continueOnFailedConnect ? ", going on" : ", stopping");
                robot.remLaser(d.laser);
                all = false;
                if (!continueOnFailedConnect) {
                    return false;
                }
            } else {
                ArLog.log(infoLogLevel, "ArLaserConnector::connectLasers: Connected %s (laser %d)", d.laser.getName(),
                        d.number);
            }
        }
        return all;
    }

    /**
     * Logs what the connector holds for each laser: whether it will connect it, and the settings the
     * command line gave, as ARIA's {@code ArLaserConnector::logLaserData} (ArLaserConnector.cpp) does;
     * then whether the arguments have been parsed. A setting not given shows as ARIA shows it unset:
     * a port of {@code (null)}, a remote TCP port of 0, and a field of view and increment of
     * {@code (inf, -inf)} and {@code -inf} (RoboSim's connector takes the field of view and increment
     * as ARIA's choices, {@code -laserDegrees} and {@code -laserIncrement}, never as degrees).
     */
    public void logLaserData() {
        for (Map.Entry<Integer, LaserData> i : lasers.entrySet()) {
            LaserData ld = i.getValue();
            ArLog.log(ArLog.Normal, "ArLaserConnector: laser #%d: %s: %s, port=%s, portType=%s, remoteTCPPort=%d,"
                    + " flipped=%d, fov=(inf, -inf), increment=-inf.", i.getKey(), ld.laser.getName(),
                    ld.connect ? "will connect to this laser" : "will NOT connect to this laser",
                    ld.port == null ? "(null)" : ld.port, ld.portType == null ? "(null)" : ld.portType,
                    ld.remoteTcpPort == null ? 0 : ld.remoteTcpPort, ld.flipped != null && ld.flipped ? 1 : 0);
        }
        if (parsed) {
            ArLog.log(ArLog.Normal, "ArLaserConnector: command-line arguments have been parsed.");
        } else {
            ArLog.log(ArLog.Normal, "ArLaserConnector: command-line arguments have not yet been parsed");
        }
    }

    /** @param number a laser's number @return the laser the connector made or was given for it, or null */
    public ArLaser getLaser(int number) {
        LaserData d = lasers.get(number);
        return d == null ? null : d.laser;
    }
}
