package robosim.bench;

import java.io.IOException;
import java.io.PrintWriter;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import robosim.env.core.Simulation;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.ServerOptions;
import robosim.env.core.Parallel;
import robosim.hw.HardwareOptions;
import robosim.params.RobotParameterFiles;
import robosim.pioneer.Commands;
import robosim.pioneer.PioneerClient;
import robosim.pioneer.server.PioneerPortOptions;
import robosim.pioneer.server.PioneerPorts;
import robosim.pioneer.server.ServedRobot;
import robosim.protocol.RobotKind;

/**
 * What a hostile ARIA client on a Pioneer port costs the rest of a run. The benchmark's grid world
 * runs at full speed (not paced in real time), its robot {@code b0} served on a Pioneer port and the
 * others driven by a client JVM ({@link BenchRobots}, sonar). An ARIA client drives {@code b0}; the
 * run's steps per second are measured while it behaves, then while it opens a flood of connections
 * to its own port, then while it floods the port with VEL commands as fast as its connection takes
 * them, until the port closes it as flooding; then how long the next client takes to connect, and
 * the rate again while it behaves. Each rate is taken after a warm-up of the same length.
 */
public final class PioneerFloodBench {
    /** The connections of the connection flood. */
    public static final int CONNECTIONS = 400;
    private static final long WAIT_MS = 60_000;

    private PioneerFloodBench() {
    }

    /**
     * The figures.
     *
     * @param robots          robots in the run, {@code b0} among them
     * @param quietStepsPerS  steps per second with an ARIA client that behaves, before the floods
     * @param floodStepsPerS  steps per second while the client floods its port with VEL
     * @param floodPackets    VEL packets the flooding client wrote in that time
     * @param refusedMs       time to open {@value #CONNECTIONS} connections to the taken port and see
     *                        every one refused
     * @param flooderClosedMs time from the start of the VEL flood until the port closed the client
     * @param nextClientMs    time for the next client to connect and open the robot
     * @param afterStepsPerS steps per second with the next client, which behaves
     */
    public record Result(int robots, double quietStepsPerS, double floodStepsPerS, long floodPackets, long refusedMs,
                         long flooderClosedMs, long nextClientMs, double afterStepsPerS) {
    }

    /**
     * Runs the benchmark.
     *
     * @param robots    robots in the grid, at least 2
     * @param seconds   how long each rate is measured
     * @param dir       where the world and the client's log go
     * @param robotFile the p3dx parameter file
     * @return the figures
     * @throws IOException          if a port or the client JVM cannot be opened
     * @throws InterruptedException if interrupted
     */
    public static Result run(int robots, double seconds, Path dir, Path robotFile) throws IOException,
            InterruptedException {
        Path worldFile = GridWorld.write(robots, dir, robotFile);
        Simulation sim = StepRateBench.load(worldFile, Parallel.SERIAL).sim();
        ServerOptions options = StepRateBench.serverOptions(0, ServerOptions.defaultThreads());
        List<Process> clients = new ArrayList<>();
        try (EnvironmentServer server = new EnvironmentServer(sim, options)) {
            server.bind();
            Thread run = new Thread(() -> {
                try {
                    server.run();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, "bench-flood-run");
            run.setDaemon(true);
            run.start();
            ServedRobot b0 = new ServedRobot("b0", RobotKind.PIONEER.id(), sim.parameters("b0"),
                    RobotParameterFiles.conversionFactors(robotFile.toString()), sim.world().stepMs());
            try {
                try (PioneerPorts ports = PioneerPorts.open(List.of(b0), new PioneerPortOptions("127.0.0.1", 0, false,
                        PioneerPortOptions.DEFAULT_WATCHDOG_MS, false, HardwareOptions.defaults()), "127.0.0.1",
                        server.robotPort(), null, code -> { })) {
                    clients.add(StepRateBench.clientJvm(server.robotPort(), new BenchRobots.Share(1, robots - 1),
                            BenchSensors.SONAR, robotFile, dir.resolve("client-flood.log"), 0, 0));
                    return measure(robots, seconds, sim, ports.portOf("b0"));
                }
            } finally {
                // every robot leaves (the port's robot as the port closes), so the run ends by itself
                StepRateBench.stop(clients);
                run.join(WAIT_MS);
            }
        }
    }

    private static Result measure(int robots, double seconds, Simulation sim, int port) throws IOException,
            InterruptedException {
        long periodNanos = (long) (seconds * 1e9);
        try (PioneerClient aria = PioneerClient.connect("127.0.0.1", port, WAIT_MS)) {
            aria.open(WAIT_MS);
            aria.startPulses();
            aria.send(Commands.comInt(Commands.ENABLE, 1));
            aria.send(Commands.comInt(Commands.VEL, 100));
            awaitSteps(sim, 1);
            stepsPerSecond(sim, periodNanos); // warming up
            double quiet = stepsPerSecond(sim, periodNanos);
            long refusedMs = refuseConnections(port);
            AtomicLong packets = new AtomicLong();
            long floodStarted = System.nanoTime();
            Thread flood = flood(aria, packets);
            double flooded = stepsPerSecond(sim, periodNanos);
            long packetsThen = packets.get();
            flood.join(WAIT_MS);
            long closedMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - floodStarted);
            long t0 = System.nanoTime();
            try (PioneerClient next = PioneerClient.connect("127.0.0.1", port, WAIT_MS)) {
                next.open(WAIT_MS);
                long nextMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - t0);
                next.startPulses();
                next.send(Commands.comInt(Commands.ENABLE, 1));
                next.send(Commands.comInt(Commands.VEL, 100));
                double after = stepsPerSecond(sim, periodNanos);
                return new Result(robots, quiet, flooded, packetsThen, refusedMs, closedMs, nextMs, after);
            }
        }
    }

    /** Waits until the run has taken this many steps. */
    private static void awaitSteps(Simulation sim, long steps) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WAIT_MS);
        while (sim.stepCount() < steps) {
            if (System.nanoTime() > deadline) {
                throw new IllegalStateException("the run did not start within " + WAIT_MS + " ms");
            }
            Thread.sleep(10);
        }
    }

    private static double stepsPerSecond(Simulation sim, long periodNanos) throws InterruptedException {
        long s0 = sim.stepCount();
        long t0 = System.nanoTime();
        TimeUnit.NANOSECONDS.sleep(periodNanos);
        long s1 = sim.stepCount();
        return (s1 - s0) / ((System.nanoTime() - t0) / 1e9);
    }

    /** Writes VEL packets as fast as the client's connection takes them, until the port closes it. */
    private static Thread flood(PioneerClient aria, AtomicLong packets) {
        byte[] one = Commands.comInt(Commands.VEL, 300).encode();
        byte[] batch = new byte[one.length * 500];
        for (int i = 0; i < 500; i++) {
            System.arraycopy(one, 0, batch, i * one.length, one.length);
        }
        Thread t = new Thread(() -> {
            long until = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WAIT_MS);
            try {
                while (System.nanoTime() < until) {
                    aria.sendRaw(batch);
                    packets.addAndGet(500);
                }
            } catch (IOException closed) {
                // the port closed the flooding client
            }
        }, "bench-vel-flood");
        t.setDaemon(true);
        t.start();
        return t;
    }

    /**
     * Opens {@value #CONNECTIONS} connections to a port a client holds, each saying nothing.
     *
     * @return ms until every one was refused
     */
    private static long refuseConnections(int port) throws IOException {
        List<Socket> flood = new ArrayList<>();
        long t0 = System.nanoTime();
        try {
            for (int i = 0; i < CONNECTIONS; i++) {
                Socket s = new Socket();
                flood.add(s);
                s.connect(new InetSocketAddress("127.0.0.1", port), (int) WAIT_MS);
            }
            for (Socket s : flood) {
                s.setSoTimeout((int) WAIT_MS);
                try {
                    if (s.getInputStream().read() >= 0) {
                        throw new IllegalStateException("a connection to a taken Pioneer port was served");
                    }
                } catch (SocketTimeoutException e) {
                    throw new IllegalStateException("a connection to a taken Pioneer port was not refused in "
                            + WAIT_MS + " ms", e);
                } catch (IOException reset) {
                    // refused
                }
            }
            return TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - t0);
        } finally {
            for (Socket s : flood) {
                s.close();
            }
        }
    }

    /**
     * Prints the figures as one line.
     *
     * @param out where
     * @param r   the figures
     */
    public static void print(PrintWriter out, Result r) {
        out.printf(Locale.ROOT, "pioneer-flood robots=%d quiet_steps_per_s=%.0f flood_steps_per_s=%.0f"
                        + " after_steps_per_s=%.0f flood_vs_quiet=%.2f flood_packets=%d refused_%d_ms=%d"
                        + " flooder_closed_ms=%d next_client_ms=%d%n", r.robots(), r.quietStepsPerS(), r.floodStepsPerS(),
                r.afterStepsPerS(), r.floodStepsPerS() / r.quietStepsPerS(), r.floodPackets(), CONNECTIONS,
                r.refusedMs(), r.flooderClosedMs(), r.nextClientMs());
        out.flush();
    }
}
