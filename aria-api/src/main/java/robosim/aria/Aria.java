package robosim.aria;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.BooleanSupplier;
import java.util.function.IntConsumer;

/**
 * ARIA's {@code Aria}: the program-wide calls a program makes around its robots. A port of an ARIA
 * program begins and ends as the C++ does:
 * <pre>{@code
 * Aria.init();
 * ArArgumentParser parser = new ArArgumentParser(args);
 * parser.loadDefaultArguments();
 * ArRobot robot = new ArRobot();
 * ArRobotConnector robotConnector = new ArRobotConnector(parser, robot);
 * if (!robotConnector.connectRobot()) {
 *     ArLog.log(ArLog.Terse, "Could not connect to the robot.");
 *     if (parser.checkHelpAndWarnUnparsed()) {
 *         Aria.logOptions();
 *         Aria.exit(1);
 *     }
 * }
 * if (!Aria.parseArgs() || !parser.checkHelpAndWarnUnparsed()) {
 *     Aria.logOptions();
 *     Aria.exit(1);
 * }
 * robot.runAsync(true);
 * ...
 * Aria.exit(0);
 * }</pre>
 *
 * <p>The connectors register what they parse and log ({@link #addParseArgsCB}, {@link
 * #addLogOptionsCB}); {@link #exit} runs the exit callbacks, disconnects the robots the connectors
 * connected, and ends the process, unless an exit handler says otherwise ({@link #setExitHandler}:
 * a program run as a thread of a bigger one must not end its JVM).
 */
public final class Aria {
    private record Callback<T>(T call, int position, String name) {
    }

    /** One program's callbacks, robots and state. */
    private static final class Program {
        final List<Callback<BooleanSupplier>> parseArgs = new ArrayList<>();
        final List<Callback<Runnable>> logOptions = new ArrayList<>();
        final List<Callback<Runnable>> exit = new ArrayList<>();
        final List<ArRobot> robots = new ArrayList<>();
        volatile boolean running;
        volatile boolean exiting;
        volatile String directory = "";
        volatile ArKeyHandler keyHandler;
        final ArConfig config = new ArConfig();
    }

    /** The program of threads that have not called {@link #init} nor been started by one that has. */
    private static final Program JVM = new Program();
    private static final InheritableThreadLocal<Program> PROGRAM = new InheritableThreadLocal<>();
    private static final InheritableThreadLocal<IntConsumer> EXIT_HANDLER = new InheritableThreadLocal<>();

    private static Program program() {
        Program p = PROGRAM.get();
        return p != null ? p : JVM;
    }

    private Aria() {
    }

    /**
     * Starts the program's ARIA state, fresh: its callbacks and robots are those of the calling
     * thread and the threads it starts from now on (each program run as threads of one JVM has its
     * own, as each ARIA process has). It is running until {@link #exit} or {@link #shutdown}.
     */
    public static void init() {
        Program p = new Program();
        p.running = true;
        PROGRAM.set(p);
    }

    /** Forgets the callbacks and robots; ARIA's {@code uninit}. */
    public static void uninit() {
        Program p = program();
        synchronized (p) {
            p.parseArgs.clear();
            p.logOptions.clear();
            p.exit.clear();
            p.robots.clear();
        }
        p.running = false;
    }

    /** @return whether {@link #init} was called and neither {@link #exit} nor {@link #shutdown} since */
    public static boolean getRunning() {
        return program().running;
    }

    /** Stops: the robots the connectors connected are disconnected; the process goes on. */
    public static void shutdown() {
        program().running = false;
        for (ArRobot r : getRobotList()) {
            r.stopRunning(true);
        }
    }

    /** Exits with code 0, as {@link #exit(int)}. */
    public static void exit() {
        exit(0);
    }

    /**
     * Runs the exit callbacks (highest position first), disconnects the robots the connectors
     * connected and exits the process with the code: ARIA's {@code Aria::exit}. A second call while
     * the first runs returns at once.
     *
     * @param exitCode the process's exit code
     */
    public static void exit(int exitCode) {
        Program p = program();
        synchronized (p) {
            p.running = false;
            if (p.exiting) {
                return;
            }
            p.exiting = true;
        }
        callExitCallbacks();
        for (ArRobot r : getRobotList()) {
            r.stopRunning(true);
        }
        IntConsumer handler = EXIT_HANDLER.get();
        (handler != null ? handler : (IntConsumer) System::exit).accept(exitCode);
    }

    /**
     * Sets what {@link #exit} does last with the exit code, for the calling thread and the threads it
     * starts from now on: {@link System#exit} unless set. Whoever runs a program as a thread of a
     * bigger one sets one that ends only that program (by throwing, say).
     *
     * @param handler the handler, or null for {@link System#exit}
     */
    public static void setExitHandler(IntConsumer handler) {
        EXIT_HANDLER.set(handler);
    }

    /** Runs the exit callbacks, highest position first. */
    public static void callExitCallbacks() {
        for (Callback<Runnable> c : sorted(program().exit)) {
            c.call().run();
        }
    }

    /**
     * @param callback run by {@link #exit}
     * @param position higher runs first (ARIA's default 50)
     */
    public static void addExitCallback(Runnable callback, int position) {
        Program p = program();
        synchronized (p) {
            p.exit.add(new Callback<>(callback, position, ""));
        }
    }

    /** @param callback run by {@link #exit}, at position 50 */
    public static void addExitCallback(Runnable callback) {
        addExitCallback(callback, 50);
    }

    /** @param callback an exit callback to forget */
    public static void remExitCallback(Runnable callback) {
        Program p = program();
        synchronized (p) {
            p.exit.removeIf(c -> c.call() == callback);
        }
    }

    /**
     * @param callback parses its part of the command line, false when it finds a bad argument
     * @param position higher runs first (ARIA's default 50; the robot connector's is 75)
     * @param name     its name, for the log
     */
    public static void addParseArgsCB(BooleanSupplier callback, int position, String name) {
        Program p = program();
        synchronized (p) {
            p.parseArgs.add(new Callback<>(callback, position, name));
        }
    }

    /** @param callback parses its arguments @param position higher runs first */
    public static void addParseArgsCB(BooleanSupplier callback, int position) {
        addParseArgsCB(callback, position, "");
    }

    /**
     * @param callback logs its options
     * @param position higher logs first (ARIA's default 50; the robot connector's is 90)
     */
    public static void addLogOptionsCB(Runnable callback, int position) {
        Program p = program();
        synchronized (p) {
            p.logOptions.add(new Callback<>(callback, position, ""));
        }
    }

    /**
     * Has every part registered parse its arguments, highest position first.
     *
     * @return false at the first that fails (logged)
     */
    public static boolean parseArgs() {
        for (Callback<BooleanSupplier> c : sorted(program().parseArgs)) {
            if (!c.call().getAsBoolean()) {
                ArLog.log(ArLog.Terse, c.name().isEmpty()
                        ? String.format("Aria::parseArgs: Failed unnamed parse arg functor (%d) returned false", c.position())
                        : String.format("Aria::parseArgs: Failed, parse arg functor '%s' (%d) returned false", c.name(),
                                c.position()));
                return false;
            }
        }
        return true;
    }

    /** Has every part registered log its options, highest position first. */
    public static void logOptions() {
        for (Callback<Runnable> c : sorted(program().logOptions)) {
            c.call().run();
            ArLog.log(ArLog.Terse, "");
        }
    }

    private static <T> List<Callback<T>> sorted(List<Callback<T>> list) {
        synchronized (program()) {
            List<Callback<T>> copy = new ArrayList<>(list);
            copy.sort(Comparator.comparingInt((Callback<T> c) -> c.position()).reversed());
            return copy;
        }
    }

    /** @param robot a robot {@link #exit} disconnects and {@link #findRobot} finds */
    public static void addRobot(ArRobot robot) {
        Program p = program();
        synchronized (p) {
            if (!p.robots.contains(robot)) {
                p.robots.add(robot);
            }
        }
    }

    /** @param robot a robot to forget */
    public static void delRobot(ArRobot robot) {
        Program p = program();
        synchronized (p) {
            p.robots.remove(robot);
        }
    }

    /**
     * @param name a robot's name
     * @return the first robot added with that name, or null
     */
    public static ArRobot findRobot(String name) {
        for (ArRobot r : getRobotList()) {
            if (r.getName().equals(name)) {
                return r;
            }
        }
        return null;
    }

    /** @return a copy of the robots added, in order */
    public static List<ArRobot> getRobotList() {
        Program p = program();
        synchronized (p) {
            return List.copyOf(p.robots);
        }
    }

    /**
     * @param dir the program's directory, where ARIA looks for its files; also the base directory of
     *            {@link #getConfig()} ({@code dir} and '/'), as ARIA's {@code Aria::setDirectory}
     */
    public static void setDirectory(String dir) {
        Program p = program();
        p.directory = dir == null ? "" : dir;
        p.config.setBaseDirectory(p.directory.isEmpty() || p.directory.endsWith("/") ? p.directory : p.directory + "/");
    }

    /** @return the program's directory, "" unless set */
    public static String getDirectory() {
        return program().directory;
    }

    /**
     * ARIA's {@code Aria::getConfig}: the program's own {@link ArConfig}, which the parts of a
     * program share. Each program ({@link #init}) has its own, as each ARIA process has.
     *
     * @return the program's config
     */
    public static ArConfig getConfig() {
        return program().config;
    }

    /** @param handler the program's key handler (ARIA keeps one, for programs that look it up) */
    public static void setKeyHandler(ArKeyHandler handler) {
        program().keyHandler = handler;
    }

    /** @return the program's key handler, or null */
    public static ArKeyHandler getKeyHandler() {
        return program().keyHandler;
    }
}
