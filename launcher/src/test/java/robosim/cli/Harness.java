package robosim.cli;

import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import robosim.env.core.Simulation;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.Bye;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.Snapshot;
import robosim.protocol.ViewerHello;

/** An Environment on loopback for a test, and the tools to watch it. Every wait is bounded. */
final class Harness implements AutoCloseable {
    final Simulation sim;
    final EnvironmentServer server;
    final CompletableFuture<RunReport> report;
    private final List<Process> processes = new ArrayList<>();

    Harness(String worldFile, ServerOptions options) throws Exception {
        World world = WorldReader.read(root().resolve("testLoadFiles/environment").resolve(worldFile));
        sim = new Simulation(world);
        server = new EnvironmentServer(sim, options);
        server.bind();
        report = CompletableFuture.supplyAsync(() -> {
            try {
                return server.run();
            } catch (InterruptedException e) {
                throw new IllegalStateException(e);
            }
        });
    }

    static Path root() {
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (p != null && !Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        return p;
    }

    Process robotJvm(String className, String name, Path log, String... args) throws Exception {
        Process p = RobotProcesses.start(className, name, server.robotPort(), log, args);
        processes.add(p);
        return p;
    }

    RunReport await() throws Exception {
        return report.get(120, TimeUnit.SECONDS);
    }

    /** Attaches a viewer that keeps every snapshot, on a thread of its own. */
    CompletableFuture<List<Snapshot>> collectSnapshots() throws Exception {
        Socket s = new Socket("127.0.0.1", server.viewerPort());
        s.setSoTimeout(60_000);
        MessageCodec codec = new MessageCodec();
        new FrameWriter(s.getOutputStream(), codec).write(new ViewerHello("test"));
        return CompletableFuture.supplyAsync(() -> {
            List<Snapshot> snapshots = new ArrayList<>();
            try (s) {
                FrameReader r = new FrameReader(s.getInputStream(), codec, 1 << 24);
                Message m;
                while ((m = r.read()) != null && !(m instanceof Bye)) {
                    if (m instanceof Snapshot f) {
                        snapshots.add(f);
                    }
                }
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
            return snapshots;
        });
    }

    @Override
    public void close() throws Exception {
        server.close();
        RobotProcesses.stop(processes);
    }
}
