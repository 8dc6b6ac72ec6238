package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import java.util.function.IntFunction;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine.Model.CommandSpec;
import robosim.cli.Main;
import robosim.examples.wander.Wander;
import robosim.protocol.Snapshot;
import robosim.protocol.recording.RecordingReader;

/**
 * Robots on other machines: the Environment in one network namespace, each robot in another, over
 * veth links through a router namespace that adds latency and jitter (see {@link NetworkNamespaces}),
 * give the very run they give on loopback, step for step. The latency comes from {@code tc netem}
 * where the kernel has it, else from a {@link DelayRelay} in the router namespace; the test says
 * which on standard error. Skipped, with a line on standard error, where network namespaces cannot
 * be made (not Linux, no iproute2, not root).
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class NetworkNamespacesTest {
    static final Path WORLD = LocalEnvironment.root().resolve("testLoadFiles/environment/small-maze.xml");
    static final List<String> ROBOTS = List.of("r1", "r2");
    static final int STEPS = 300;
    static final long SEED = 5;
    /** Added once each way between the Environment and a robot: a step's round trip gains about twice it. */
    static final int DELAY_MS = 10;
    static final int JITTER_MS = 5;
    private static final Duration START = Duration.ofSeconds(60);
    private static final Duration RUN = Duration.ofSeconds(90);
    private static final Pattern ROBOT_PORT = Pattern.compile("robots on \\S+:(\\d+),");
    private static final String TOKEN = String.format("%016x", ThreadLocalRandom.current().nextLong());

    private static NetworkNamespaces net;
    private static String unavailable;

    @TempDir
    Path dir;

    /** Where a robot's JVM runs (the command prefix) and the address it dials. */
    private record Dial(List<String> prefix, String host, int port) { }

    /** Sets up how robots reach an Environment that listens on a port; may start JVMs (added to the list). */
    private interface Route {
        List<Dial> open(int envPort, List<JvmProcess> jvms) throws Exception;
    }

    @BeforeAll
    static void makeNamespaces() throws Exception {
        try {
            net = NetworkNamespaces.create(ROBOTS.size());
        } catch (NetworkNamespaces.Unavailable e) {
            unavailable = "NetworkNamespacesTest skipped: cannot make network namespaces here: " + e.getMessage();
            System.err.println(unavailable);
        }
    }

    /** Skips each test, rather than the class, so that reports count it as skipped and show why. */
    @BeforeEach
    void needNamespaces() {
        Assumptions.assumeTrue(net != null, unavailable);
    }

    @AfterAll
    static void deleteNamespaces() throws Exception {
        if (net != null) {
            net.close();
        }
    }

    /*
     * THE RUN SECRET is handed out here, and only here. The Environment takes it as --token, once
     * its command line has that option (asked of the command's own spec, so that the test runs
     * before and after the secret exists); every JVM the test starts gets it in ROBOSIM_TOKEN, where
     * robot clients read it. An Environment bound to an address other than loopback refuses to run
     * without a secret; the loopback run presents the same secret, to be the same run.
     */
    private static List<String> secretArgs() {
        CommandSpec env = Main.commandLine().getSubcommands().get("env").getCommandSpec();
        return env.findOption("--token") != null ? List.of("--token", TOKEN) : List.of();
    }

    private Map<String, String> secretEnvironment() {
        // the Environment's secret files go to the test's folder, not the user's home
        return Map.of("ROBOSIM_TOKEN", TOKEN, "ROBOSIM_TOKEN_DIR", dir.resolve("tokens").toString());
    }

    @Test
    void aRunAcrossNamespacesWithLatencyAndJitterEqualsTheSameRunOnLoopback() throws Exception {
        Path loopback = dir.resolve("loopback.rsr");
        Path across = dir.resolve("across.rsr");
        long start = System.nanoTime();
        List<String> loopbackReport = run("loopback", loopback, List.of(), "127.0.0.1",
                (port, jvms) -> eachRobot(i -> new Dial(List.of(), "127.0.0.1", port)));
        long middle = System.nanoTime();
        List<String> acrossReport = run("across namespaces", across, net.exec(net.env()), NetworkNamespaces.ENV_ADDRESS,
                latency());
        System.err.printf(Locale.ROOT, "NetworkNamespacesTest: %d steps, JVM starts included: %.1f s on loopback, "
                + "%.1f s across namespaces%n", STEPS, (middle - start) / 1e9, (System.nanoTime() - middle) / 1e9);
        assertEquals(loopbackReport, acrossReport, "the Environment's report");
        assertSameRun(loopback, across);
    }

    /** Adds latency and jitter between the namespaces: netem where the kernel has it, else a relay. */
    private Route latency() throws Exception {
        Optional<String> noNetem = net.addNetem(DELAY_MS, JITTER_MS);
        if (noNetem.isEmpty()) {
            System.err.printf(Locale.ROOT, "NetworkNamespacesTest: latency by tc netem, %d ms ± %d ms on each of the "
                    + "router's links%n", DELAY_MS, JITTER_MS);
            return (port, jvms) -> eachRobot(i -> new Dial(net.exec(net.robots(i)), NetworkNamespaces.ENV_ADDRESS,
                    port));
        }
        System.err.printf(Locale.ROOT, "NetworkNamespacesTest: no tc netem here (%s); latency by DelayRelay in "
                + "namespace %s, %d ms ± %d ms each way%n", noNetem.get(), net.router(), DELAY_MS, JITTER_MS);
        return (port, jvms) -> {
            JvmProcess relay = JvmProcess.start("relay", net.exec(net.router()), Map.of(), DelayRelay.class.getName(),
                    List.of("0", NetworkNamespaces.ENV_ADDRESS, Integer.toString(port), Integer.toString(DELAY_MS),
                            Integer.toString(JITTER_MS), Long.toString(SEED)));
            jvms.add(relay);
            String line = relay.awaitLine("DelayRelay: listening on port ", START);
            int relayPort = Integer.parseInt(line.replaceFirst("DelayRelay: listening on port (\\d+),.*", "$1"));
            return eachRobot(i -> new Dial(net.exec(net.robots(i)), net.gateway(i), relayPort));
        };
    }

    /** @return a dial for each robot, made from its number, 1 to the number of robots */
    private static List<Dial> eachRobot(IntFunction<Dial> dial) {
        List<Dial> dials = new ArrayList<>();
        for (int i = 1; i <= ROBOTS.size(); i++) {
            dials.add(dial.apply(i));
        }
        return dials;
    }

    /**
     * Runs the world: the Environment's JVM, recording with sensors, then a Wander robot JVM per
     * robot; every JVM is ended when the run is over or has failed.
     *
     * @return the Environment's report lines (the end and each robot's)
     */
    private List<String> run(String where, Path recording, List<String> envPrefix, String bind, Route route)
            throws Exception {
        List<JvmProcess> jvms = new ArrayList<>();
        try {
            List<String> envArgs = new ArrayList<>(List.of("env", WORLD.toString(), "--bind", bind, "--port", "0",
                    "--viewer-port", "0", "--seed", Long.toString(SEED), "--steps", Integer.toString(STEPS),
                    "--connect-timeout", "60", "--record", recording.toString(), "--record-sensors"));
            envArgs.addAll(secretArgs());
            JvmProcess env = JvmProcess.start("env (" + where + ")", envPrefix, secretEnvironment(),
                    Main.class.getName(), envArgs);
            jvms.add(env);
            Matcher port = ROBOT_PORT.matcher(env.awaitLine("Environment: ", START));
            assertTrue(port.find(), "the Environment prints its robot port: " + env.output());
            List<Dial> dials = route.open(Integer.parseInt(port.group(1)), jvms);
            List<JvmProcess> robots = new ArrayList<>();
            for (int i = 0; i < ROBOTS.size(); i++) {
                Dial d = dials.get(i);
                JvmProcess robot = JvmProcess.start(ROBOTS.get(i) + " (" + where + ")", d.prefix(), secretEnvironment(),
                        Main.class.getName(), List.of("robot", Wander.class.getName(), ROBOTS.get(i), d.host(),
                                Integer.toString(d.port())));
                jvms.add(robot);
                robots.add(robot);
            }
            assertEquals(0, env.awaitExit(RUN), "the Environment " + where + " ended well:\n" + env.output());
            for (JvmProcess robot : robots) {
                assertEquals(0, robot.awaitExit(Duration.ofSeconds(30)),
                        "a robot " + where + " ended well:\n" + robot.output());
            }
            return env.lines().stream().filter(l -> l.startsWith("Run ended") || l.startsWith("robot ")).toList();
        } finally {
            for (JvmProcess p : jvms) {
                p.close();
            }
        }
    }

    /** The two recordings hold the same world and the same snapshot at every step, byte for byte. */
    private static void assertSameRun(Path expected, Path actual) throws Exception {
        try (RecordingReader a = RecordingReader.open(expected); RecordingReader b = RecordingReader.open(actual)) {
            Snapshot first = null;
            Snapshot last = null;
            for (Snapshot s = a.next(); s != null; s = a.next()) {
                Snapshot t = b.next();
                assertNotNull(t, "the run across namespaces ended before step " + s.step());
                assertEquals(describe(s), describe(t), "step " + s.step());
                first = first == null ? s : first;
                last = s;
            }
            assertNull(b.next(), "the run across namespaces went on after step " + a.lastStep());
            assertEquals(a.endReason(), b.endReason());
            assertEquals(STEPS, last.step(), a.endReason());
            Snapshot.RobotView from = first.robots().get(0);
            Snapshot.RobotView to = last.robots().get(0);
            assertTrue(Math.hypot(to.x() - from.x(), to.y() - from.y()) > 500, "r1 wandered: " + describe(last));
        }
        assertEquals(-1, Files.mismatch(expected, actual), "the recordings differ at this byte offset");
    }

    /** @return everything a snapshot holds, arrays included, a line per robot */
    private static String describe(Snapshot s) {
        StringBuilder b = new StringBuilder("step " + s.step() + " t " + s.timeMs());
        for (Snapshot.RobotView v : s.robots()) {
            b.append(String.format(Locale.ROOT, "%n%s (%s, %s, %s) stalled %s connected %s vel %s/%s "
                    + "odo (%s, %s, %s) sonar %s laser %s@%s", v.name(), v.x(), v.y(), v.th(), v.stalled(),
                    v.connected(), v.vel(), v.rotVel(), v.odoX(), v.odoY(), v.odoTh(), Arrays.toString(v.sonar()),
                    Arrays.toString(v.laser()), v.laserIncrement()));
        }
        return b.append("\nmessages ").append(s.messages()).append(" said ").append(s.said()).toString();
    }
}
