package robosim.remote;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.function.BooleanSupplier;
import robosim.env.core.Simulation;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.Await;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.SnapshotListener;

/**
 * An Environment in the test's JVM on loopback and free ports, paced in real time as a person
 * driving by hand sees it, its step loop on a thread of its own; it keeps the latest true state of
 * each robot for the test to check. {@link #close()} closes it.
 */
public final class LiveEnvironment implements AutoCloseable {
    private final EnvironmentServer server;
    private final CompletableFuture<RunReport> report = new CompletableFuture<>();
    private volatile Snapshot latest;

    /**
     * @param dir      where to write the world file
     * @param worldXml the world, with {@code %ROBOTS%} for the shipped robots' folder
     * @throws Exception if it cannot start
     */
    public LiveEnvironment(Path dir, String worldXml) throws Exception {
        String robots = root().resolve("testLoadFiles/robots").toString();
        Path world = Files.writeString(dir.resolve("world.xml"), worldXml.replace("%ROBOTS%", robots));
        ServerOptions o = ServerOptions.loopback();
        server = new EnvironmentServer(new Simulation(WorldReader.read(world), 1),
                new ServerOptions(o.bindAddress(), 0, 0, 0, true, o.stepTimeoutMs(), 30_000, 0, o.maxFrame()));
        server.bind();
        server.addSnapshotListener(new SnapshotListener() {
            @Override
            public void world(WorldDescription w) {
                // only the robots' state is checked
            }

            @Override
            public void snapshot(Snapshot s) {
                latest = s;
            }
        });
        Thread t = new Thread(() -> {
            try {
                report.complete(server.run());
            } catch (InterruptedException | RuntimeException e) {
                report.completeExceptionally(e);
            }
        }, "environment");
        t.setDaemon(true);
        t.start();
    }

    /** @return the RoboSim root: the nearest folder above the working directory that holds testLoadFiles */
    static Path root() {
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (p != null && !Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        return p;
    }

    /** @return the robots' port */
    public int robotPort() {
        return server.robotPort();
    }

    /** @return the viewers' port */
    public int viewerPort() {
        return server.viewerPort();
    }

    /** @param name a robot @return its true state at the latest step, or null before the first */
    public Snapshot.RobotView robot(String name) {
        Snapshot s = latest;
        return s == null ? null : s.robots().stream().filter(r -> r.name().equals(name)).findFirst().orElse(null);
    }

    /**
     * Waits, polling, for a condition.
     *
     * @param condition what to wait for
     * @param timeoutMs the longest wait
     * @return whether it came true in time
     */
    public static boolean await(BooleanSupplier condition, long timeoutMs) {
        return Await.within(Duration.ofMillis(timeoutMs), condition);
    }

    /** @return the latest step run, 0 before the first */
    public long step() {
        Snapshot s = latest;
        return s == null ? 0 : s.step();
    }

    /**
     * Waits until the run has gone on for some steps: what a robot was told before now has reached
     * the Environment and been acted on.
     *
     * @param steps how many steps
     * @return whether they ran within a few seconds
     */
    public boolean awaitSteps(int steps) {
        long until = step() + steps;
        return await(() -> step() >= until, 5_000L + 200L * steps);
    }

    @Override
    public void close() {
        server.close();
    }
}
