package robosim.cli;

import java.io.PrintWriter;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;

/**
 * The robot programs {@code robosim env --in-process} runs in the Environment's JVM: each robot's
 * program's {@code main(NAME, 127.0.0.1, PORT)} on a thread of its own, as {@code robosim robot}
 * would run it in a JVM of its own. The program is unchanged: its robots connect to the
 * Environment's address as always, and reach it through the in-process link the Environment admits.
 *
 * <p>{@code --in-process CLASS} gives CLASS to every robot of the world not given a program by name;
 * {@code --in-process ROBOT=CLASS} gives one robot its own.
 */
final class InProcessPrograms {
    /** How long the programs may go on once the run is over, ms: they end as their robots are told so. */
    static final long GRACE_MS = 2_000;

    private final Map<String, Method> programs;
    private final List<Thread> threads = new ArrayList<>();
    private final Map<String, Throwable> failures = new ConcurrentHashMap<>();

    private InProcessPrograms(Map<String, Method> programs) {
        this.programs = programs;
    }

    /**
     * Matches the programs asked for to the world's robots.
     *
     * @param specs  the {@code --in-process} values: {@code CLASS} or {@code ROBOT=CLASS}
     * @param robots the robots the world names, in order
     * @param loader where the programs' classes come from
     * @return the programs, one per robot
     * @throws IllegalArgumentException naming the value and the rule, if a value names no class with a
     *                                  static {@code main(String[])}, or a robot the world does not name,
     *                                  or if a robot has no program while others have
     */
    static InProcessPrograms of(List<String> specs, List<String> robots, ClassLoader loader) {
        Method forAll = null;
        Map<String, Method> named = new LinkedHashMap<>();
        for (String spec : specs) {
            int eq = spec.indexOf('=');
            Method main = main(spec, eq < 0 ? spec : spec.substring(eq + 1), loader);
            if (eq < 0) {
                if (forAll != null) {
                    throw new IllegalArgumentException("'" + spec + "' was supplied for --in-process: only one CLASS may"
                            + " go to every robot; give the others as ROBOT=CLASS");
                }
                forAll = main;
                continue;
            }
            String robot = spec.substring(0, eq).trim();
            named.put(robot, main);
        }
        Map<String, Method> programs = new LinkedHashMap<>();
        for (String robot : robots) {
            Method main = named.getOrDefault(robot, forAll);
            if (main == null) {
                throw new IllegalArgumentException("robot " + robot + " has no program: --in-process CLASS gives one to"
                        + " every robot, --in-process " + robot + "=CLASS to it alone");
            }
            programs.put(robot, main);
        }
        for (String robot : named.keySet()) {
            if (!programs.containsKey(robot)) {
                // an open world takes robots it does not name
                programs.put(robot, named.get(robot));
            }
        }
        return new InProcessPrograms(programs);
    }

    private static Method main(String spec, String className, ClassLoader loader) {
        String rule = ": it is CLASS or ROBOT=CLASS, a class with a public static main(String[]) on RoboSim's"
                + " classpath or --classpath";
        try {
            Method m = Class.forName(className.trim(), true, loader).getMethod("main", String[].class);
            if (!Modifier.isStatic(m.getModifiers())) {
                throw new IllegalArgumentException("'" + spec + "' was supplied for --in-process" + rule);
            }
            return m;
        } catch (ClassNotFoundException | NoSuchMethodException | LinkageError e) {
            throw new IllegalArgumentException("'" + spec + "' was supplied for --in-process" + rule, e);
        }
    }

    /** @return the robots that have a program, in order */
    List<String> robots() {
        return List.copyOf(programs.keySet());
    }

    /**
     * Starts every program, each on a thread of its own. A program that throws is told at once, with
     * its trace, while the Environment goes on (and waits for its robot, if it had not connected).
     *
     * @param port the Environment's robot port
     * @param err  where a failure is told
     */
    void start(int port, PrintWriter err) {
        for (Map.Entry<String, Method> p : programs.entrySet()) {
            String robot = p.getKey();
            Method main = p.getValue();
            Thread t = new Thread(() -> {
                Throwable failure = null;
                try {
                    main.invoke(null, (Object) new String[] {robot, "127.0.0.1", Integer.toString(port)});
                } catch (InvocationTargetException e) {
                    failure = e.getCause();
                } catch (IllegalAccessException | RuntimeException e) {
                    failure = e;
                }
                if (failure != null) {
                    failures.put(robot, failure);
                    synchronized (err) {
                        err.println("robosim env: robot " + robot + "'s program failed:");
                        ProgramTrace.print(failure, err);
                        err.flush();
                    }
                }
            }, "robot-program-" + robot);
            t.setContextClassLoader(main.getDeclaringClass().getClassLoader());
            t.setDaemon(true);
            threads.add(t);
            t.start();
        }
    }

    /**
     * Gives the programs {@link #GRACE_MS} to end once the run is over.
     *
     * @return whether every program ended without throwing (a failure was told as it came)
     * @throws InterruptedException if interrupted while waiting
     */
    boolean finish() throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(GRACE_MS);
        for (Thread t : threads) {
            t.join(Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
        }
        return failures.isEmpty();
    }
}
