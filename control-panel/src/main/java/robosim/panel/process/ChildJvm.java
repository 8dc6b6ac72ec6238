package robosim.panel.process;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * A RoboSim command in a JVM of its own: {@code java -cp CLASSPATH robosim.cli.Main ARGS...}, with
 * this JVM's classpath unless told otherwise, its output and errors merged and handed line by line
 * to a sink on a daemon thread. {@link #stop()} ends it and the processes it started.
 */
public final class ChildJvm implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(ChildJvm.class.getName());
    /** The launcher's entry point, named rather than linked: the panel does not depend on the launcher. */
    public static final String MAIN = "robosim.cli.Main";
    /** The system property naming RoboSim's folder, passed on to the JVMs started. */
    static final String ROOT = "robosim.root";
    /** How long {@link #stop()} waits for a polite end before it forces one. */
    static final long GRACE_MS = 3000;

    private final String label;
    private final Process process;

    private ChildJvm(String label, Process process) {
        this.label = label;
        this.process = process;
    }

    /**
     * @param label     what the JVM is, for the log (for example {@code environment})
     * @param classpath the classpath, or null for this JVM's
     * @param args      the arguments of {@code robosim.cli.Main}
     * @param env       variables to add to the JVM's environment
     * @param lines     where each line of its output goes; called on a thread of its own
     * @return the started JVM
     * @throws IOException if the JVM cannot be started
     */
    public static ChildJvm start(String label, String classpath, List<String> args, Map<String, String> env,
                                 Consumer<String> lines) throws IOException {
        return start(label, classpath, MAIN, args, env, lines);
    }

    /** As {@link #start(String, String, List, Map, Consumer)}, with another main class (for tests). */
    static ChildJvm start(String label, String classpath, String mainClass, List<String> args, Map<String, String> env,
                          Consumer<String> lines) throws IOException {
        List<String> command = new ArrayList<>(List.of(javaBinary()));
        String root = System.getProperty(ROOT);
        if (root != null) {
            // where RoboSim's shipped worlds and robot files are, as bin/robosim told this JVM
            command.add("-D" + ROOT + "=" + root);
        }
        command.addAll(List.of("-cp", classpath != null ? classpath : System.getProperty("java.class.path"), mainClass));
        command.addAll(args);
        ProcessBuilder b = new ProcessBuilder(command).redirectErrorStream(true);
        b.environment().putAll(env);
        Process p = b.start();
        LOG.fine(() -> "started " + label + " (pid " + p.pid() + "): " + String.join(" ", args));
        Thread pump = new Thread(() -> pump(p, lines), label + "-output");
        pump.setDaemon(true);
        pump.start();
        return new ChildJvm(label, p);
    }

    private static void pump(Process p, Consumer<String> lines) {
        try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = r.readLine()) != null) {
                lines.accept(line);
            }
        } catch (IOException e) {
            // the stream closes when the JVM is stopped: nothing more to read
            LOG.log(Level.FINE, "output of pid " + p.pid() + " ended", e);
        }
    }

    /** @return the java binary of this JVM, so the child runs on the same Java */
    static String javaBinary() {
        return Path.of(System.getProperty("java.home"), "bin", "java").toString();
    }

    /** @return whether the JVM still runs */
    public boolean isAlive() {
        return process.isAlive();
    }

    /** @return what the JVM is, as given when started */
    public String label() {
        return label;
    }

    /** @return the JVM's process id */
    public long pid() {
        return process.pid();
    }

    /**
     * Waits for the JVM to end by itself.
     *
     * @param ms the longest wait
     * @return its exit code, or null if it still runs
     * @throws InterruptedException if interrupted while waiting
     */
    public Integer waitFor(long ms) throws InterruptedException {
        return process.waitFor(ms, TimeUnit.MILLISECONDS) ? process.exitValue() : null;
    }

    /**
     * Ends the JVM and what it started: asked politely first (its shutdown hooks remove its secret
     * files), forced after {@link #GRACE_MS}. Bounded: returns within about twice that.
     */
    public void stop() {
        List<ProcessHandle> children = process.descendants().toList();
        process.destroy();
        children.forEach(ProcessHandle::destroy);
        try {
            if (!process.waitFor(GRACE_MS, TimeUnit.MILLISECONDS)) {
                process.destroyForcibly();
                process.waitFor(GRACE_MS, TimeUnit.MILLISECONDS);
            }
        } catch (InterruptedException e) {
            process.destroyForcibly();
            Thread.currentThread().interrupt();
        }
        children.stream().filter(ProcessHandle::isAlive).forEach(ProcessHandle::destroyForcibly);
    }

    @Override
    public void close() {
        stop();
    }
}
