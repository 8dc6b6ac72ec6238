package robosim.it;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArRobot;
import robosim.aria.ArUtil;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.hw.EnvironmentLinks;
import robosim.hw.RobotRuntime;
import robosim.hw.RuntimeChoices;
import robosim.protocol.MessageCodec;
import robosim.protocol.Snapshot;

/**
 * Many robots of one JVM over one connection (a shared link): the same run as over a connection
 * each, robots that stop answering dropped alone, and programs that open several robots sharing a
 * link without knowing it.
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class SharedLinkTest {
    @TempDir
    Path dir;

    /**
     * A room of {@code robots} Pioneers on a grid, 1.5 m apart (0.8 m from 17 robots on), close
     * enough to see and bump into each other, with a 0.2 m pillar at every third corner between
     * them, and sonar and odometry noise.
     */
    private Path room(int robots) throws Exception {
        int side = (int) Math.ceil(Math.sqrt(robots));
        int spacing = robots <= 16 ? 1500 : 800;
        int size = side * spacing + 1000;
        StringBuilder xml = new StringBuilder(String.format(Locale.ROOT, "<world name=\"crowd\" width=\"%d\""
                + " height=\"%d\" stepMs=\"100\" boundary=\"true\">%n  <noise sonar=\"5\" odometry=\"0.005\"/>%n",
                size, size));
        for (int i = 1; i < side; i++) {
            for (int j = 1; j < side; j++) {
                if ((i + j) % 3 == 0) {
                    int x = 500 + i * spacing;
                    int y = 500 + j * spacing;
                    xml.append(String.format(Locale.ROOT, "  <polygon points=\"%d,%d %d,%d %d,%d %d,%d\"/>%n",
                            x - 100, y - 100, x + 100, y - 100, x + 100, y + 100, x - 100, y + 100));
                }
            }
        }
        for (int k = 0; k < robots; k++) {
            int x = 500 + spacing / 2 + (k % side) * spacing;
            int y = 500 + spacing / 2 + (k / side) * spacing;
            xml.append(String.format(Locale.ROOT,
                    "  <robot name=\"b%d\" type=\"pioneer\" x=\"%d\" y=\"%d\" th=\"%d\" params=\"%%ROBOTS%%/p3dx.p\"/>%n",
                    k, x, y, (37 * k) % 360));
        }
        return ThreadedRun.world(dir, "crowd-" + robots + ".xml", xml.append("</world>\n").toString());
    }

    /** A runtime of the test's own whose robots reach the Environment as {@code mode} says. */
    private static RobotRuntime links(EnvironmentLinks.Mode mode) {
        return RobotRuntime.create("links-" + mode.name().toLowerCase(Locale.ROOT), RuntimeChoices.defaults().withLinks(mode));
    }

    /** Drives by its sonars until the run ends: ahead while the front is clear, else turning. */
    private static Boolean wander(String name, int port, RobotRuntime runtime) {
        ArRobot robot = new ArRobot(name, "127.0.0.1", port, "p3dx");
        robot.setRuntime(runtime);
        if (!robot.blockingConnect()) {
            throw new IllegalStateException(name + ": " + robot.getConnectionError());
        }
        robot.enableMotors();
        while (robot.isConnected()) {
            boolean blocked = robot.getClosestSonarRange(-45, 45) < 700;
            robot.setVel(blocked ? 0 : 350);
            robot.setRotVel(blocked ? 40 : (robot.getStep() % 17) - 8);
            ArUtil.sleep(100);
        }
        return true;
    }

    /**
     * Runs {@code robots} wanderers for {@code steps} steps on {@code runtime}: one with the links it
     * chooses, or null for the default runtime, as a program that does not know of runtimes.
     */
    private List<Snapshot> run(Path world, int robots, long steps, RobotRuntime runtime) throws Exception {
        try (ThreadedRun run = new ThreadedRun(world, 7, steps)) {
            List<Future<Boolean>> programs = new ArrayList<>();
            for (int k = 0; k < robots; k++) {
                String name = "b" + k;
                programs.add(run.robot(() -> wander(name, run.port(), runtime)));
            }
            RunReport report = run.await();
            assertEquals("step limit " + steps + " reached", report.endReason());
            for (Future<Boolean> p : programs) {
                assertTrue(p.get(30, TimeUnit.SECONDS));
            }
            synchronized (run.snapshots) {
                return new ArrayList<>(run.snapshots);
            }
        }
    }

    @Test
    void oneConnectionForManyRobotsGivesTheRunOfAConnectionEach() throws Exception {
        Path world = room(12);

        List<Snapshot> own = run(world, 12, 150, links(EnvironmentLinks.Mode.OWN));
        List<Snapshot> shared = run(world, 12, 150, links(EnvironmentLinks.Mode.SHARED));

        assertEquals(151, own.size());
        assertEquals(own.size(), shared.size());
        MessageCodec codec = new MessageCodec();
        for (int i = 0; i < own.size(); i++) {
            assertArrayEquals(codec.encode(own.get(i)), codec.encode(shared.get(i)),
                    "step " + own.get(i).step() + ": poses, sonar readings and messages");
        }
        Snapshot last = own.get(own.size() - 1);
        assertTrue(last.robots().stream().anyMatch(r -> Math.hypot(r.x() - own.get(0).robots().get(0).x(),
                r.y() - own.get(0).robots().get(0).y()) > 1), "the robots moved");
    }

    @Test
    void twoOfTwoHundredRobotsOnOneLinkThatStopAnsweringAreDroppedAloneAtTheDeadline() throws Exception {
        RobotRuntime runtime = links(EnvironmentLinks.Mode.SHARED);
        int robots = 200;
        long steps = 12;
        Set<String> stuck = Set.of("b17", "b123");
        AtomicBoolean spinning = new AtomicBoolean(true);
        ServerOptions options = new ServerOptions("127.0.0.1", 0, 0, steps, false, 1_000, 60_000, 0, 4 << 20);
        List<Thread> programs = new ArrayList<>();
        List<String> ended = java.util.Collections.synchronizedList(new ArrayList<>());
        try (LogCapture log = new LogCapture("robosim.env.net");
             LocalEnvironment env = new LocalEnvironment(WorldReader.read(room(robots)), 1, options)) {
            for (int k = 0; k < robots; k++) {
                String name = "b" + k;
                Thread t = new Thread(() -> {
                    ArRobot robot = new ArRobot(name, "127.0.0.1", env.server.robotPort(), "p3dx");
                    robot.setRuntime(runtime);
                    if (!robot.blockingConnect()) {
                        return;
                    }
                    robot.enableMotors();
                    while (robot.isConnected()) {
                        if (stuck.contains(name) && robot.getStep() >= 5) {
                            while (spinning.get() && robot.isConnected()) {
                                Thread.onSpinWait(); // computing, never yielding to the simulation
                            }
                        }
                        robot.setVel(100);
                        ArUtil.sleep(100);
                    }
                    ended.add(name);
                }, "robot-" + name);
                t.setDaemon(true);
                programs.add(t);
                t.start();
            }

            RunReport report = env.await();

            assertEquals("step limit " + steps + " reached", report.endReason(), "the run went on without them");
            assertEquals(steps, report.steps());
            List<String> dropped = log.warnings().stream().filter(w -> w.startsWith("closing robot")).toList();
            assertEquals(2, dropped.size(), log.warnings().toString());
            for (String name : stuck) {
                assertTrue(dropped.stream().anyMatch(w -> w.startsWith("closing robot " + name
                        + ": it did not send its requests for step 6 within 1000 ms")), dropped.toString());
            }
            assertTrue(log.lines().stream().anyMatch(l -> l.contains("on a shared link")), "the robots shared a link");
        } finally {
            spinning.set(false);
            for (Thread t : programs) {
                t.join(10_000);
                assertFalse(t.isAlive(), t.getName() + " has stopped");
            }
        }
        assertEquals(robots, ended.size(), "every program learnt that its run ended");
    }

    @Test
    void aProgramThatOpensSeveralRobotsSharesALinkWithoutKnowing() throws Exception {
        Path world = room(3);
        Logger net = Logger.getLogger("robosim.env.net");
        Level was = net.getLevel();
        net.setLevel(Level.INFO);
        try (LogCapture log = new LogCapture("robosim.env.net")) {
            List<Snapshot> auto = run(world, 3, 60, null);
            List<Snapshot> own = run(world, 3, 60, links(EnvironmentLinks.Mode.OWN));

            List<String> connected = log.lines().stream().filter(l -> l.startsWith("robot ") && l.contains(" connected")).toList();
            assertEquals(6, connected.size(), connected.toString());
            assertEquals(2, connected.subList(0, 3).stream().filter(l -> l.contains("on a shared link")).count(),
                    "with the default links, the first robot of the program has a connection of its own and the"
                            + " others share one: " + connected);
            assertTrue(connected.subList(3, 6).stream().noneMatch(l -> l.contains("on a shared link")), connected.toString());
            MessageCodec codec = new MessageCodec();
            assertEquals(own.size(), auto.size());
            for (int i = 0; i < own.size(); i++) {
                assertArrayEquals(codec.encode(own.get(i)), codec.encode(auto.get(i)), "step " + i);
            }
        } finally {
            net.setLevel(was);
        }
    }
}
