package robosim.experiment;

import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * The robot programs of one run: threads of this JVM, or JVMs of their own. A program that fails
 * while the run is under way (it throws, or its JVM exits with an error) stops the run at once: the
 * thread running the Environment is interrupted, so that the run does not wait for a robot that
 * will never come or step again. Once the run is over, the programs get {@link #GRACE_MS} to end.
 */
final class RunRobots {
    /** How long programs may go on once the run is over, ms: they end as their robots are told so. */
    static final long GRACE_MS = 2_000;
    /** How many of a failed robot JVM's last log lines its run's failure quotes. */
    static final int LOG_TAIL = 5;

    private final ClassLoader loader;
    private final RobotJvms jvms;
    private final Thread runner;
    private final List<Thread> threads = new ArrayList<>();
    /** The robot JVMs; guarded by this. */
    private final List<Process> processes = new ArrayList<>();
    /** The failures, in the order they came: robot, then what went wrong; guarded by this. */
    private final Map<String, String> failures = new LinkedHashMap<>();
    /** Whether the run is under way, so a failure interrupts the runner; guarded by this. */
    private boolean armed;
    /** Whether the run is over and the robot JVMs are being stopped; guarded by this. */
    private boolean stopping;

    /**
     * @param loader where the programs' classes come from
     * @param jvms   how to start a program in a JVM of its own, or null if none may be
     * @param runner the thread that runs the Environment
     */
    RunRobots(ClassLoader loader, RobotJvms jvms, Thread runner) {
        this.loader = loader;
        this.jvms = jvms;
        this.runner = runner;
    }

    /**
     * @param className a program's class
     * @return its {@code main}
     * @throws RunFailure if it has none
     */
    Method main(String className) {
        try {
            Method m = Class.forName(className, true, loader).getMethod("main", String[].class);
            if (!Modifier.isStatic(m.getModifiers())) {
                throw new RunFailure("program " + className + "'s main is not static");
            }
            return m;
        } catch (ClassNotFoundException | NoSuchMethodException | LinkageError e) {
            throw new RunFailure("program " + className + " is no class with a public static main(String[]) on"
                    + " RoboSim's classpath or --classpath (" + e + ")");
        }
    }

    /** Starts a robot's program on a thread of this JVM. */
    void startThread(String robot, Method main, List<String> args) {
        Thread t = new Thread(() -> {
            Throwable failure = null;
            try {
                main.invoke(null, (Object) args.toArray(String[]::new));
            } catch (InvocationTargetException e) {
                failure = e.getCause();
            } catch (IllegalAccessException | RuntimeException e) {
                failure = e;
            }
            if (failure != null) {
                fail(robot, "robot " + robot + "'s program failed: " + describe(failure));
            }
        }, "robot-program-" + robot);
        t.setContextClassLoader(loader);
        t.setDaemon(true);
        threads.add(t);
        t.start();
    }

    /** Starts a robot's program in a JVM of its own. */
    void startJvm(String className, String robot, int port, String secret, Path log, List<String> args)
            throws IOException {
        if (jvms == null) {
            throw new RunFailure("program " + className + " asks for link: jvm, but this runner cannot start JVMs");
        }
        Files.createDirectories(log.getParent());
        Process p = jvms.start(className, robot, port, secret, log, args);
        synchronized (this) {
            processes.add(p);
        }
        p.onExit().thenAccept(ended -> {
            int exit = ended.exitValue();
            synchronized (this) {
                if (exit == 0 || stopping) {
                    return;
                }
            }
            fail(robot, "robot " + robot + "'s JVM exited with code " + exit + "; the end of its log (" + log + "): "
                    + tail(log));
        });
    }

    /** The run starts: a failure from now on stops it, and one that came before stops it at once. */
    synchronized void arm() {
        armed = true;
        if (!failures.isEmpty()) {
            runner.interrupt();
        }
    }

    /** The run is over: no interrupt comes after this, and none that came before it is left pending. */
    synchronized void disarm() {
        armed = false;
        Thread.interrupted();
    }

    private synchronized void fail(String robot, String reason) {
        failures.putIfAbsent(robot, reason);
        if (armed) {
            runner.interrupt();
        }
    }

    /** @return the first failure, or null if none */
    synchronized String failure() {
        return failures.isEmpty() ? null : failures.values().iterator().next();
    }

    /**
     * Gives the programs {@link #GRACE_MS} to end, then stops the robot JVMs that are left, all
     * against one deadline. A JVM stopped here is no failure: its robot's part had ended with the run.
     *
     * @throws InterruptedException if interrupted (the JVMs are stopped all the same)
     */
    void finish() throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(GRACE_MS);
        try {
            for (Thread t : threads) {
                t.join(Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
            }
            List<Process> all;
            synchronized (this) {
                all = new ArrayList<>(processes);
            }
            for (Process p : all) {
                p.waitFor(Math.max(1, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
            }
        } finally {
            List<Process> left;
            synchronized (this) {
                stopping = true;
                left = processes.stream().filter(Process::isAlive).toList();
            }
            for (Process p : left) {
                p.destroy();
            }
            for (Process p : left) {
                if (!p.waitFor(5, TimeUnit.SECONDS)) {
                    p.destroyForcibly();
                }
            }
        }
    }

    static String describe(Throwable t) {
        StackTraceElement[] trace = t.getStackTrace();
        return trace.length == 0 ? t.toString() : t + " at " + trace[0];
    }

    static String tail(Path log) {
        try {
            List<String> lines = Files.readAllLines(log, StandardCharsets.UTF_8);
            return String.join(" | ", lines.subList(Math.max(0, lines.size() - LOG_TAIL), lines.size()));
        } catch (IOException e) {
            return "(unreadable: " + e.getMessage() + ")";
        }
    }

    /** A run that cannot go on, with the reason its record gives. */
    static final class RunFailure extends RuntimeException {
        private static final long serialVersionUID = 1L;

        RunFailure(String message) {
            super(message);
        }
    }
}
