package robosim.it;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.SnapshotListener;

/**
 * An Environment on loopback, in this JVM, with robot programs as threads of their own (not pool
 * threads: each robot blocks for the whole run). Keeps every snapshot. Every wait is bounded.
 */
final class ThreadedRun implements AutoCloseable {
    final LocalEnvironment env;
    final List<Snapshot> snapshots = new ArrayList<>();
    private final ExecutorService threads = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "robot-program");
        t.setDaemon(true);
        return t;
    });

    /**
     * @param world    the world file
     * @param seed     the run's seed
     * @param maxSteps steps to run, 0 until every robot has left
     */
    ThreadedRun(Path world, long seed, long maxSteps) throws Exception {
        this(world, seed, maxSteps, false);
    }

    /**
     * @param world     the world file
     * @param seed      the run's seed
     * @param maxSteps  steps to run, 0 until every robot has left
     * @param inProcess whether the robots reach the Environment in-process instead of over TCP
     */
    ThreadedRun(Path world, long seed, long maxSteps, boolean inProcess) throws Exception {
        env = new LocalEnvironment(WorldReader.read(world), seed, ServerOptions.loopback().withMaxSteps(maxSteps),
                inProcess, new SnapshotListener() {
            @Override
            public void world(WorldDescription w) {
            }

            @Override
            public void snapshot(Snapshot f) {
                synchronized (snapshots) {
                    snapshots.add(f);
                }
            }
        });
    }

    /** Writes a world file into {@code dir}; {@code %s} in the text stands for the robots/ folder. */
    static Path world(Path dir, String name, String xml) throws Exception {
        String robots = LocalEnvironment.root().resolve("testLoadFiles/robots").toString();
        return Files.writeString(dir.resolve(name), xml.replace("%ROBOTS%", robots));
    }

    /** @return the Environment's robot port */
    int port() {
        return env.robotPort();
    }

    /** Starts a robot program on a thread of its own. */
    <T> Future<T> robot(Callable<T> program) {
        return threads.submit(program);
    }

    /** @return the report, once the run has ended */
    RunReport await() throws Exception {
        return env.await();
    }

    @Override
    public void close() throws Exception {
        try {
            env.close();
        } finally {
            threads.shutdownNow();
        }
    }
}
