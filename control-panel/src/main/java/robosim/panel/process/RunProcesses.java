package robosim.panel.process;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import robosim.panel.model.EnvironmentLine;
import robosim.panel.model.RobotLaunch;
import robosim.panel.model.RunSettings;
import robosim.protocol.RunSecret;

/**
 * The JVMs one panel started: at most one Environment, and the robot programs and RemoteControl
 * windows added to it. Each one's output goes to the log with its label in front. {@link #close()}
 * stops them all; the Environment's secret file lives in a folder of this panel's own, removed then.
 */
public final class RunProcesses implements AutoCloseable {
    private final Consumer<String> log;
    private final List<ChildJvm> children = new CopyOnWriteArrayList<>();
    private final String classpath;
    private ChildJvm environment;
    private Path secretDir;
    /** Stops the JVMs started here when this JVM ends without the window being closed (Ctrl-C, a kill). */
    private final Thread hook = new Thread(this::closeQuietly, "panel-stop-children");

    /**
     * @param classpath the classpath of the JVMs started, or null for this JVM's
     * @param log       where every line of their output goes, prefixed with what they are
     */
    public RunProcesses(String classpath, Consumer<String> log) {
        this.classpath = classpath;
        this.log = log;
        Runtime.getRuntime().addShutdownHook(hook);
    }


    /**
     * Starts an Environment. Its secret is written to a file only this user can read, which robots
     * started here are told of.
     *
     * @param settings the new run's settings
     * @param ready    gets where it listens, once it says so (on the output's thread)
     * @return its JVM
     * @throws IOException if it cannot be started
     * @throws IllegalStateException if an Environment started here still runs
     */
    public synchronized ChildJvm startEnvironment(RunSettings settings, Consumer<EnvironmentLine> ready)
            throws IOException {
        if (environment != null && environment.isAlive()) {
            throw new IllegalStateException("an Environment started by this panel still runs (pid "
                    + environment.pid() + "): stop it first");
        }
        if (secretDir == null) {
            secretDir = Files.createTempDirectory("robosim-panel");
        }
        Path secret = secretFile();
        Files.deleteIfExists(secret);
        environment = ChildJvm.start("env", classpath, settings.envArguments(secret), Map.of(), line -> {
            log.accept("env: " + line);
            EnvironmentLine.parse(line).ifPresent(ready);
        });
        children.add(environment);
        return environment;
    }

    /** @return the file the Environment started here writes its secret to, or null before one started */
    public synchronized Path secretFile() {
        return secretDir == null ? null : secretDir.resolve("secret");
    }

    /**
     * @return the secret of the Environment started here, or null when there is none (yet)
     * @throws IOException if the file cannot be read
     */
    public synchronized String secret() throws IOException {
        Path f = secretFile();
        return f == null || !Files.isRegularFile(f) ? null : RunSecret.check(Files.readString(f).strip());
    }

    /**
     * Starts a robot program in a JVM of its own.
     *
     * @param launch    what to start
     * @param host      the Environment's host
     * @param robotPort its robot port
     * @return the JVM
     * @throws IOException if it cannot be started
     */
    public ChildJvm startRobot(RobotLaunch launch, String host, int robotPort) throws IOException {
        return startTool("robot " + launch.name(), launch.robotArguments(host, robotPort));
    }

    /**
     * Starts a RoboSim command in a JVM of its own (a RemoteControl window, for one), told of the
     * secret of an Environment started here.
     *
     * @param label what it is, for the log
     * @param args  the arguments of {@code robosim.cli.Main}
     * @return the JVM
     * @throws IOException if it cannot be started
     */
    public ChildJvm startTool(String label, List<String> args) throws IOException {
        Path f = secretFile();
        Map<String, String> env = f != null && Files.isRegularFile(f)
                ? Map.of(RunSecret.FILE_ENV, f.toString()) : Map.of();
        ChildJvm jvm = ChildJvm.start(label, classpath, args, env, line -> log.accept(label + ": " + line));
        children.add(jvm);
        return jvm;
    }

    /** @return whether an Environment started here runs */
    public synchronized boolean environmentRuns() {
        return environment != null && environment.isAlive();
    }

    /** Stops the Environment started here, if any, and every robot started for it. */
    public synchronized void stopAll() {
        List<ChildJvm> all = new ArrayList<>(children);
        children.clear();
        // robots first, so that they end with a bye rather than see the Environment vanish
        for (int i = all.size() - 1; i >= 0; i--) {
            all.get(i).stop();
        }
        environment = null;
    }

    private void closeQuietly() {
        try {
            close();
        } catch (IOException e) {
            log.accept("panel: cannot remove the secret's folder " + secretDir + ": " + e.getMessage());
        }
    }

    @Override
    public synchronized void close() throws IOException {
        stopAll();
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException e) {
            // this JVM is ending: the hook runs, or has run, stopAll itself
        }
        if (secretDir != null) {
            Files.deleteIfExists(secretDir.resolve("secret"));
            Files.deleteIfExists(secretDir);
            secretDir = null;
        }
    }
}
