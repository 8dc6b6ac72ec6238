package robosim.it;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import robosim.aria.ArRobot;
import robosim.cli.RobotProcesses;
import robosim.examples.wander.Wander;
import robosim.env.core.Simulation;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.recording.SnapshotListener;
import robosim.cli.Background;

/**
 * The one way the end-to-end tests start an Environment: in this JVM, on loopback and free ports,
 * its step loop on a thread of its own from the moment it is made. Robots reach it over TCP like any
 * robot (as threads of the test, or JVMs started by {@link #robotJvm}), viewers through its viewer
 * port. Every wait is bounded; {@link #close()} closes the server and stops the robot JVMs.
 */
final class LocalEnvironment implements AutoCloseable {
    final Simulation sim;
    final EnvironmentServer server;
    private final CompletableFuture<RunReport> report;
    private final List<Process> processes = new ArrayList<>();

    /**
     * A shipped world with seed 1.
     *
     * @param worldFile a file of {@code testLoadFiles/environment/}
     * @param options   how the server runs
     */
    LocalEnvironment(String worldFile, ServerOptions options) throws Exception {
        this(shipped(worldFile), 1, options);
    }

    /**
     * @param world     the world
     * @param seed      the run's seed
     * @param options   how the server runs
     * @param listeners follow the run from its first step, as a recorder does
     */
    LocalEnvironment(World world, long seed, ServerOptions options, SnapshotListener... listeners) throws Exception {
        this(world, seed, options, false, listeners);
    }

    /**
     * @param world     the world
     * @param seed      the run's seed
     * @param options   how the server runs
     * @param inProcess whether robots of this JVM reach it in-process, without TCP
     * @param listeners follow the run from its first step, as a recorder does
     */
    LocalEnvironment(World world, long seed, ServerOptions options, boolean inProcess, SnapshotListener... listeners)
            throws Exception {
        sim = new Simulation(world, seed);
        server = new EnvironmentServer(sim, options);
        server.bind();
        if (inProcess) {
            server.admitInProcess();
        }
        for (SnapshotListener l : listeners) {
            server.addSnapshotListener(l);
        }
        report = Background.supply("environment", () -> {
            try {
                return server.run();
            } catch (InterruptedException e) {
                throw new IllegalStateException(e);
            }
        });
    }

    /** @return the RoboSim root: the nearest folder above the working directory that holds testLoadFiles */
    static Path root() {
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (p != null && !Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        return p;
    }

    /** @return a world of {@code testLoadFiles/environment/}, read */
    static World shipped(String worldFile) {
        return WorldReader.read(root().resolve("testLoadFiles/environment").resolve(worldFile));
    }

    /** @return the port robots connect to */
    int robotPort() {
        return server.robotPort();
    }

    /** @return the port viewers connect to */
    int viewerPort() {
        return server.viewerPort();
    }

    /** Starts a robot program in a JVM of its own, stopped by {@link #close()} if it has not ended. */
    Process robotJvm(String className, String name, Path log, String... args) throws Exception {
        Process p = RobotProcesses.start(className, name, server.robotPort(), log, args);
        processes.add(p);
        return p;
    }

    /**
     * Starts a Wander program (a Pioneer as ARIA sees it) for each of the world's robots, each on a
     * daemon thread of this JVM that ends with its run.
     *
     * @return the threads, in the world's order
     */
    List<Thread> wanderers() {
        List<Thread> robots = new ArrayList<>();
        for (String name : sim.robotNames()) {
            Thread t = new Thread(() -> {
                ArRobot robot = new ArRobot(name, "127.0.0.1", robotPort(), "p3dx");
                if (robot.blockingConnect()) {
                    robot.enableMotors();
                    new Wander(robot).run();
                }
            }, "wander-" + name);
            t.setDaemon(true);
            t.start();
            robots.add(t);
        }
        return robots;
    }

    /** @return the run's report, within two minutes */
    RunReport await() throws Exception {
        return await(120);
    }

    /** @return the run's report, within the given seconds */
    RunReport await(long seconds) throws Exception {
        return report.get(seconds, TimeUnit.SECONDS);
    }

    @Override
    public void close() throws Exception {
        server.close();
        RobotProcesses.stop(processes);
    }
}
