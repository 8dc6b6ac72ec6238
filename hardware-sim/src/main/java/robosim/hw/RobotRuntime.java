package robosim.hw;

import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.regex.Pattern;

/**
 * What the robots of one program share in this JVM: the watchdog thread that looks after them, their
 * links to the Environment (the shared link to each Environment, and how many robots reach each),
 * the {@link RunEndWatch}es that follow them, and the simulated clock that threads outside any
 * robot's code read ({@code ArTime}). Each robot keeps its own hardware, request queue and state.
 *
 * <p>A robot given no runtime ({@code new ArRobot(...)} and nothing more) uses the <em>default
 * runtime</em>, made on first use with the choices the system properties say
 * ({@link RuntimeChoices#fromSystemProperties()}). A program that runs several teams, or a test that
 * wants its robots apart from any others in the JVM, makes runtimes of its own and gives one to each
 * of its robots before they connect:
 *
 * <pre>{@code
 * RobotRuntime team = RobotRuntime.create("team-a", RuntimeChoices.defaults().withLinks(EnvironmentLinks.Mode.SHARED));
 * ArRobot r1 = new ArRobot("r1", host, port, "p3dx");
 * r1.setRuntime(team);
 * r1.blockingConnect();
 * }</pre>
 *
 * <p>A runtime opens with its first robot (a robot uses it from the moment it begins to connect
 * until its part in the run ends) and closes when its last robot leaves: its threads stop and its
 * links close. A runtime made with {@link #create} opens again for the next robot given it. A robot
 * given no runtime joins the default runtime while other robots use it; otherwise it makes a fresh
 * default runtime, which reads the system properties then, and the one before stays closed.
 */
public final class RobotRuntime {
    /** The default runtime's name. */
    public static final String DEFAULT_NAME = "default";
    private static final Pattern NAME = Pattern.compile("[A-Za-z0-9][A-Za-z0-9._-]{0,31}");
    /** Guards {@link #defaultRuntime}. */
    private static final Object DEFAULT_LOCK = new Object();
    /** The default-runtime holder: the one robots given none use now or used last, null before the first. */
    private static RobotRuntime defaultRuntime;

    private final String name;
    private final RuntimeChoices choices;
    private final boolean isDefault;
    private final RunEndWatches runEndWatches;
    private final SharedLinks sharedLinks = new SharedLinks(this);
    /** Robots connected or connecting, by the Environment's host and port. */
    private final Map<String, Integer> robotsByEnvironment = new ConcurrentHashMap<>();
    /** The robots the watchdog looks after: welcomed and not yet ended. */
    private final Set<HardwareSimulator> watched = ConcurrentHashMap.newKeySet();
    private volatile long latestMs;
    /** Robots using the runtime; guarded by this. */
    private int robots;
    /** Running while the runtime has robots; guarded by this. */
    private Watchdog watchdog;

    private RobotRuntime(String name, RuntimeChoices choices, boolean isDefault, RunEndWatches runEndWatches) {
        this.name = name;
        this.choices = choices;
        this.isDefault = isDefault;
        this.runEndWatches = runEndWatches;
    }

    /**
     * Makes a runtime for robots to be given ({@link AbstractRobot#setRuntime}).
     *
     * @param name    a name for its threads ({@code hw-watchdog-<name>}) and messages: a letter or
     *                digit, then up to 31 letters, digits, {@code .}, {@code _} or {@code -}
     * @param choices how its robots reach the Environment and what threads read their links
     * @return the runtime; it opens with the first robot that connects with it
     * @throws IllegalArgumentException if the name breaks its rule, or choices is null
     */
    public static RobotRuntime create(String name, RuntimeChoices choices) {
        if (name == null || !NAME.matcher(name).matches()) {
            throw new IllegalArgumentException("'" + name + "' was supplied for a runtime's name: it is a letter or"
                    + " digit, then up to 31 letters, digits, '.', '_' or '-'");
        }
        if (choices == null) {
            throw new IllegalArgumentException("null was supplied for a runtime's choices");
        }
        return new RobotRuntime(name, choices, false, new RunEndWatches());
    }

    /**
     * Makes a runtime with the choices the system properties say now.
     *
     * @param name a name, as {@link #create(String, RuntimeChoices)} has it
     * @return the runtime
     * @throws IllegalArgumentException if the name breaks its rule, or a system property names no choice
     */
    public static RobotRuntime create(String name) {
        return create(name, RuntimeChoices.fromSystemProperties());
    }

    /**
     * @return the default runtime if one has been made: the one robots given no runtime use now, or
     *         the last they used (closed, its clock where its robots left it)
     */
    public static Optional<RobotRuntime> currentDefault() {
        synchronized (DEFAULT_LOCK) {
            return Optional.ofNullable(defaultRuntime);
        }
    }

    /**
     * @return the default runtime, made (not yet open) if there has been none; a robot that connects
     *         while it has no robots makes a fresh one
     */
    static RobotRuntime defaultRuntime() {
        synchronized (DEFAULT_LOCK) {
            if (defaultRuntime == null) {
                defaultRuntime = new RobotRuntime(DEFAULT_NAME, RuntimeChoices.fromSystemProperties(), true,
                        new RunEndWatches());
            }
            return defaultRuntime;
        }
    }

    /**
     * A robot begins to use a runtime: the one it was given, else the default runtime (a fresh one if
     * the last has closed). It leaves it with {@link #leave()}.
     *
     * @param given the robot's runtime, or null for the default
     * @return the runtime it uses, open
     */
    static RobotRuntime enter(RobotRuntime given) {
        if (given != null && !given.isDefault) {
            given.enter(true);
            return given;
        }
        synchronized (DEFAULT_LOCK) {
            RobotRuntime current = defaultRuntime;
            if (current != null && current.enter(false)) {
                return current;
            }
            // the watches follow every default runtime's robots, so the fresh one takes them over
            defaultRuntime = new RobotRuntime(DEFAULT_NAME, RuntimeChoices.fromSystemProperties(), true,
                    current == null ? new RunEndWatches() : current.runEndWatches);
            defaultRuntime.enter(true);
            return defaultRuntime;
        }
    }

    /**
     * A robot begins to use the runtime, which opens if it is the first.
     *
     * @param mayOpen whether it may be the first; if not, it enters only a runtime open now
     * @return whether it entered
     */
    private synchronized boolean enter(boolean mayOpen) {
        if (robots == 0 && !mayOpen) {
            return false;
        }
        if (robots++ == 0) {
            watchdog = Watchdog.start(name, watched, sharedLinks);
        }
        return true;
    }

    /** A robot's part ended: it no longer uses the runtime, which closes if it was the last. */
    synchronized void leave() {
        if (robots == 0 || --robots > 0) {
            return;
        }
        watchdog.stop();
        watchdog = null;
        sharedLinks.closeAll("the program's robots of runtime " + name + " have all left");
    }

    /** @return the runtime's name */
    public String name() {
        return name;
    }

    /** @return how its robots reach the Environment and what threads read their links */
    public RuntimeChoices choices() {
        return choices;
    }

    /** @return whether this is a default runtime (one robots given no runtime use) */
    public boolean isDefault() {
        return isDefault;
    }

    /** @return whether robots use the runtime now (its threads run) */
    public synchronized boolean isOpen() {
        return robots > 0;
    }

    /** @return how many robots use it now: connecting or in their run */
    public synchronized int robots() {
        return robots;
    }

    /**
     * @return the simulated time of the latest state one of its robots received, ms (0 before any):
     *         "now" for a thread outside any robot's code
     */
    public long latestTimeMs() {
        return latestMs;
    }

    /** @param timeMs the simulated time of a state one of its robots received */
    void stateArrived(long timeMs) {
        latestMs = timeMs;
    }

    /** @return the watches that follow its robots */
    RunEndWatches runEndWatches() {
        return runEndWatches;
    }

    /** @return its shared links, one per Environment */
    SharedLinks sharedLinks() {
        return sharedLinks;
    }

    /**
     * Counts a robot that reaches an Environment, until the robot's link closes.
     *
     * @param environment the Environment's {@code host:port}
     * @return how many of its robots reach it, this one included
     */
    int countRobotAt(String environment) {
        return robotsByEnvironment.merge(environment, 1, Integer::sum);
    }

    /** @param environment the Environment's {@code host:port}, whose robot's link has closed */
    void uncountRobotAt(String environment) {
        robotsByEnvironment.computeIfPresent(environment, (k, n) -> n > 1 ? n - 1 : null);
    }

    /** @param hw a robot, welcomed, for the watchdog to look after */
    void watch(HardwareSimulator hw) {
        watched.add(hw);
    }

    /** @param hw a robot whose part ended */
    void unwatch(HardwareSimulator hw) {
        watched.remove(hw);
    }

    /**
     * Makes a thread, not yet started, that reads a link and runs its robots' cycles: a platform
     * daemon thread whatever the runtime's choice. It blocks in the socket's read itself, where a
     * virtual thread would park and be woken through the JDK's poller thread and then a carrier:
     * one hand-off more each step (measured in docs/BENCHMARKS.md, 2026-11-28, the wire's pace).
     *
     * @param threadName the thread's name
     * @param task       what it runs
     * @return the thread
     */
    Thread readerThread(String threadName, Runnable task) {
        return RobotThreads.unstarted(threadName, task, false);
    }

    @Override
    public String toString() {
        return "runtime " + name;
    }
}
