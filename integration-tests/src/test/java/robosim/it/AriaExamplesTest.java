package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArLog;
import robosim.aria.Aria;
import robosim.cli.Background;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;
import robosim.examples.aria.ActionExample;
import robosim.examples.aria.LaserConnect;
import robosim.examples.aria.LineFinderExample;
import robosim.examples.aria.RobotConnectionCallbacks;
import robosim.examples.aria.RobotSyncTaskExample;
import robosim.examples.aria.SimpleConnect;
import robosim.examples.aria.SimpleMotionCommands;
import robosim.examples.aria.ThreadExample;
import robosim.examples.aria.TwoRobotWander;
import robosim.examples.aria.Wander;

/**
 * AriaCoda's examples ported to Java ({@code examples/aria}), run as ARIA programs run: through
 * {@code Aria}, {@code ArArgumentParser} and {@code ArRobotConnector}, against a RoboSim Environment
 * in lockstep ({@code NAME HOST PORT}) and against RoboSim's Pioneer port ({@code -remoteHost}).
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class AriaExamplesTest {
    @TempDir
    Path dir;

    /** What an example printed, and the code it gave {@code Aria.exit}. */
    record Ran(String out, int exit) {
    }

    /** Aria.exit ends the example's thread, not the test's JVM. */
    static final class Exited extends RuntimeException {
        final int code;

        Exited(int code) {
            super("Aria.exit(" + code + ")", null, false, false);
            this.code = code;
        }
    }

    /**
     * Runs an example's main as its program, its log and its exit caught: the first code given to
     * Aria.exit, from whichever of its threads (a key handler's Escape exits from the robot's cycle).
     */
    static Ran run(Consumer<String[]> main, String... args) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        ArLog.setStream(new PrintStream(bytes, true, StandardCharsets.UTF_8));
        java.util.concurrent.atomic.AtomicInteger code = new java.util.concurrent.atomic.AtomicInteger(-1);
        Aria.setExitHandler(c -> {
            code.compareAndSet(-1, c);
            throw new Exited(c);
        });
        try {
            main.accept(args);
        } catch (Exited e) {
            // the program ended here
        } finally {
            ArLog.setStream(null);
            Aria.setExitHandler(null);
        }
        return new Ran(bytes.toString(StandardCharsets.UTF_8), code.get());
    }

    /** Runs an example whose key handler reads standard input, with these keys on it. */
    static Ran runWithKeys(String keys, Consumer<String[]> main, String... args) {
        return runWithInput(new java.io.ByteArrayInputStream(keys.getBytes(StandardCharsets.ISO_8859_1)), main, args);
    }

    /** Runs an example whose key handler reads standard input, with this stream as the keyboard. */
    static Ran runWithInput(java.io.InputStream keys, Consumer<String[]> main, String... args) {
        synchronized (System.class) {
            java.io.InputStream in = System.in;
            System.setIn(keys);
            try {
                return run(main, args);
            } finally {
                System.setIn(in);
            }
        }
    }

    @Test
    void simpleConnectConnectsToTheEnvironmentPrintsThePoseSleepsThreeSecondsAndExits() throws Exception {
        try (ThreadedRun run = new ThreadedRun(LocalEnvironment.root().resolve("testLoadFiles/environment/empty-room.xml"),
                1, 600)) {
            Future<Ran> r1 = run.robot(() -> run(SimpleConnect::main, "r1", "127.0.0.1", String.valueOf(run.port())));
            Future<Ran> r2 = run.robot(() -> run(SimpleConnect::main, "r2", "127.0.0.1", String.valueOf(run.port())));
            Ran ran = r1.get(90, TimeUnit.SECONDS);
            Ran other = r2.get(90, TimeUnit.SECONDS);
            RunReport report = run.await();
            assertEquals(0, ran.exit(), ran.out());
            assertEquals(0, other.exit(), other.out());
            assertTrue(ran.out().contains("simpleConnect: Connected to robot.\n"), ran.out());
            assertTrue(ran.out().contains("simpleConnect: Pose=(1500.00,1500.00,45.00), Trans.  Vel=0.00, Battery=13.00V"
                    + "\n"), ran.out());
            assertTrue(other.out().contains("simpleConnect: Pose=(4500.00,4500.00,-135.00)"), other.out());
            assertTrue(ran.out().endsWith("simpleConnect: Ending robot thread...\nDisconnecting from robot.\n"
                    + "simpleConnect: Exiting.\n"), ran.out());
            // 3 s of 100 ms steps, and the connection's first steps
            assertTrue(report.steps() >= 30 && report.steps() < 40, "steps: " + report.steps());
        }
    }

    @Test
    void simpleConnectReachesThePioneerPortWithRemoteHost() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), false, code -> { })) {
            Ran ran = Background.supply("simpleConnect", () -> run(SimpleConnect::main, "-remoteHost", "127.0.0.1",
                    "-rrtp", String.valueOf(run.ports.portOf("r1")))).get(90, TimeUnit.SECONDS);
            assertEquals(0, ran.exit(), ran.out());
            assertTrue(ran.out().contains("Connnecting to robot using TCP connection to 127.0.0.1:"), ran.out());
            assertTrue(ran.out().contains("Connected to remote host 127.0.0.1 through tcp.\n\n"), ran.out());
            // a Pioneer server's odometry starts where the robot does, as a real Pioneer's
            assertTrue(ran.out().contains("simpleConnect: Pose=(0.00,0.00,0.00), Trans.  Vel=0.00"), ran.out());
            assertTrue(ran.out().contains("simpleConnect: Exiting."), ran.out());
        }
    }

    @Test
    void aBadArgumentOrNoServerEndsWithTheReasonAndTheOptions() {
        Ran bad = run(SimpleConnect::main, "-rrtp", "eighty");
        assertEquals(1, bad.exit(), bad.out());
        assertTrue(bad.out().startsWith("Argument given to -rrtp was not an integer it was the string eighty\n"
                + "simpleConnect: Could not connect to the robot.\n"), bad.out());
        assertTrue(bad.out().contains("Options for ArRobotConnector"), bad.out());
        // nobody listens on the port: the connection fails, saying where it looked
        Ran none = run(SimpleConnect::main, "-rh", "127.0.0.1", "-rrtp", "1");
        assertEquals(1, none.exit(), none.out());
        assertTrue(none.out().contains("Could not connect robot to remote host 127.0.0.1, port 1."), none.out());
        Ran help = run(SimpleConnect::main, "-help", "-rh", "127.0.0.1", "-rrtp", "1");
        assertEquals(1, help.exit(), help.out());
        assertTrue(help.out().contains("-remoteHost <remoteHostNameOrIP>"), help.out());
    }

    @Test
    void simpleMotionCommandsDrivesTurnsAndDrivesAgainAsTheCommandsSay() throws Exception {
        PioneerRun.room(dir);
        try (ThreadedRun run = new ThreadedRun(dir.resolve("room.xml"), 1, 1000)) {
            Future<Ran> r1 = run.robot(() -> run(SimpleMotionCommands::main, "r1", "127.0.0.1",
                    String.valueOf(run.port())));
            Ran ran = r1.get(120, TimeUnit.SECONDS);
            RunReport report = run.await();
            assertEquals(0, ran.exit(), ran.out());
            assertEquals(2, ran.out().lines().filter(l -> l.startsWith("simpleMotionCommands: Pose=")).count(), ran.out());
            RobotSummary r = report.robots().get(0);
            // 0° + 50° − 100° = −50°; about 1.2 m at 250 mm/s and 0.7 m at 150 mm/s, less the ramps
            assertEquals(-50, r.th(), 2, "heading: " + r);
            assertEquals(1900, r.distance(), 150, "distance: " + r);
            assertTrue(ran.out().endsWith("simpleMotionCommands: Exiting.\n"), ran.out());
        }
    }

    @Test
    void wanderDrivesAboutTheRoomWithItsActionsAndTheLaserUntilTheRunEnds() throws Exception {
        PioneerRun.room(dir);
        try (ThreadedRun run = new ThreadedRun(dir.resolve("room.xml"), 1, 600)) {
            Future<Ran> r1 = run.robot(() -> runWithKeys("", Wander::main, "r1", "127.0.0.1",
                    String.valueOf(run.port()), "-connectLaser"));
            RunReport report = run.await();
            Ran ran = r1.get(60, TimeUnit.SECONDS);
            assertEquals(0, ran.exit(), ran.out());
            assertTrue(!ran.out().contains("unable to connect to requested lasers"), ran.out());
            RobotSummary r = report.robots().get(0);
            // 60 s at up to 400 mm/s in a 10 m room: it drives, and turns before the walls
            assertTrue(r.distance() > 5000, "distance: " + r);
            assertEquals(0, r.collisions(), "collisions: " + r);
        }
    }

    @Test
    void escapeEndsWander() throws Exception {
        PioneerRun.room(dir);
        try (ThreadedRun run = new ThreadedRun(dir.resolve("room.xml"), 1, 600)) {
            Future<Ran> r1 = run.robot(() -> runWithKeys("\u001b", Wander::main, "r1", "127.0.0.1",
                    String.valueOf(run.port())));
            Ran ran = r1.get(60, TimeUnit.SECONDS);
            RunReport report = run.await();
            assertEquals(0, ran.exit(), ran.out());
            assertTrue(ran.out().contains("Escape was pressed, program is exiting."), ran.out());
            assertTrue(report.steps() < 100, "it left at once: " + report.steps());
        }
    }

    @Test
    void actionExamplesGoAndTurnDriveTheRoomWithoutTouchingAWall() throws Exception {
        PioneerRun.room(dir);
        try (ThreadedRun run = new ThreadedRun(dir.resolve("room.xml"), 1, 900)) {
            Future<Ran> r1 = run.robot(() -> run(ActionExample::main, "r1", "127.0.0.1", String.valueOf(run.port())));
            RunReport report = run.await();
            Ran ran = r1.get(60, TimeUnit.SECONDS);
            assertEquals(0, ran.exit(), ran.out());
            assertTrue(ran.out().contains("actionExample: Connected to robot."), ran.out());
            RobotSummary r = report.robots().get(0);
            // Go drives at up to 500 mm/s and stops 350 mm short; Turn turns away within 400 mm
            assertTrue(r.distance() > 3000, "distance: " + r);
            assertEquals(0, r.collisions(), "collisions: " + r);
        }
    }

    @Test
    void laserConnectConnectsTheLaserTheCommandLineAsksForAndPrintsItsClosestReading() throws Exception {
        PioneerRun.room(dir);
        try (ThreadedRun run = new ThreadedRun(dir.resolve("room.xml"), 1, 120)) {
            Future<Ran> r1 = run.robot(() -> run(LaserConnect::main, "r1", "127.0.0.1", String.valueOf(run.port()),
                    "-connectLaser", "-laserDegrees", "100"));
            run.await();
            Ran ran = r1.get(60, TimeUnit.SECONDS);
            assertEquals(0, ran.exit(), ran.out());
            assertTrue(ran.out().contains("Connected to all lasers."), ran.out());
            // r1 at (3000, 3000) faces +x; the boundary's inner faces are at 100 and 9900. In 100° of
            // view the nearest is the wall on the right, at the view's edge: the beam at -50° from the
            // laser (18 mm ahead) meets y = 100 2900 / sin 50° = 3786 mm out, at (5451, 100), 3797 mm
            // from the centre, which polar readings are measured from. The 20 beams from about 30° to
            // 50° left reach 8 m (the far corner) without a hit: 81 of 101.
            double beam = 2900 / Math.sin(Math.toRadians(50));
            double closest = Math.hypot(18 + beam * Math.cos(Math.toRadians(50)), 2900);
            assertTrue(ran.out().contains(String.format(java.util.Locale.ROOT, "Laser #1 (lms2xx_1): connected. Have 81"
                    + " 'current' readings. Closest reading is at -50 degrees and is %.3f", closest / 1000)), ran.out());
            assertEquals(3, ran.out().lines().filter(l -> l.startsWith("Laser #1")).count(), "every 5 s of 12: " + ran.out());
            assertTrue(ran.out().endsWith("lasersExample: exiting.\n"), ran.out());
        }
    }

    @Test
    void laserConnectReadsTheLaserThroughThePioneerPortToo() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), 120, false, code -> { })) {
            Ran ran = Background.supply("laserConnect", () -> run(LaserConnect::main, "-remoteHost", "127.0.0.1",
                    "-rrtp", String.valueOf(run.ports.portOf("r1")), "-connectLaser")).get(90, TimeUnit.SECONDS);
            assertEquals(0, ran.exit(), ran.out());
            // the room as in the lockstep run, its full 180° this time: the wall on the right, 2900 mm
            // from the laser at -90°, is the nearest
            assertTrue(java.util.regex.Pattern.compile("Laser #1 \\(lms2xx_1\\): connected\\. Have \\d{2,3} 'current'"
                    + " readings\\. Closest reading is at -9\\d degrees and is 2\\.9\\d+ meters away\\.").matcher(ran.out())
                    .find(), ran.out());
        }
    }

    @Test
    void aConnectionOfTheProgramsOwnSendsTheRobotToThatPioneerServer() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), 0, false, code -> { })) {
            int port = run.ports.portOf("r1");
            robosim.aria.ArTcpConnection refused = new robosim.aria.ArTcpConnection();
            int ret = refused.open("127.0.0.1", 1);
            assertEquals(robosim.aria.ArTcpConnection.OPEN_CON_REFUSED, ret);
            assertEquals("Connection refused.", refused.getOpenMessage(ret));
            String moved = Background.supply("own connection", () -> {
                robosim.aria.ArTcpConnection con = new robosim.aria.ArTcpConnection();
                assertEquals(0, con.open("127.0.0.1", port));
                robosim.aria.ArRobot robot = new robosim.aria.ArRobot();
                robot.setDeviceConnection(con);
                assertTrue(robot.blockingConnect(), robot.getConnectionError());
                robot.enableMotors();
                robot.move(500);
                for (int i = 0; i < 100 && !robot.isMoveDone(); i++) {
                    robosim.aria.ArUtil.sleep(100);
                }
                String at = String.format(java.util.Locale.ROOT, "%.0f", robot.getX());
                robot.disconnect();
                return at;
            }).get(60, TimeUnit.SECONDS);
            assertEquals(500, Double.parseDouble(moved), 45, "the robot's odometry, through the Pioneer port");
            assertEquals(3500, run.env.sim.summary("r1").x(), 60, "the robot of the Environment behind the port moved");
        }
    }

    @Test
    void twoRobotWanderDrivesTwoRobotsThroughTheirOwnConnectionsAndStopsOneAfterTenSeconds() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.roomForTwo(dir), 150, false, code -> { })) {
            Ran ran = Background.supply("twoRobotWander", () -> run(TwoRobotWander::main, "-rh1", "127.0.0.1", "-rp1",
                    String.valueOf(run.ports.portOf("r1")), "-rh2", "127.0.0.1", "-rp2",
                    String.valueOf(run.ports.portOf("r2")))).get(90, TimeUnit.SECONDS);
            assertEquals(0, ran.exit(), ran.out());
            assertTrue(ran.out().contains("Connecting to second robot at 127.0.0.1:"), ran.out());
            assertTrue(!ran.out().contains("through tcp"), "its own connections, not the connector's: " + ran.out());
            // each robot's own connection logs ARIA's lines, with the name the Pioneer server gives it
            assertTrue(ran.out().contains("Connected to robot.\nName: r1\nType: Pioneer\nSubtype: p3dx\n"), ran.out());
            assertTrue(ran.out().contains("Connected to robot.\nName: r2\n"), ran.out());
            assertEquals(1, ran.out().lines().filter(l -> l.equals("Switching to robot 2.")).count(), ran.out());
            assertTrue(ran.out().endsWith("Both robots disconnected.\n"), ran.out());
            RobotSummary r1 = run.env.sim.summary("r1");
            RobotSummary r2 = run.env.sim.summary("r2");
            // one thread drives both: while it sleeps on one robot, the other's steps go on too. Both
            // wander at 400 mm/s; r1 is stopped after 10 s of the run's 15
            assertTrue(r1.distance() > 2000, "r1: " + r1);
            assertTrue(r2.distance() > r1.distance() + 1000, "r2 went on: " + r2 + " / " + r1);
            assertEquals(0, r1.collisions() + r2.collisions(), r1 + " / " + r2);
        }
    }

    @Test
    void robotConnectionCallbacksRunAtTheirMomentsAndTheSonarIsTurnedOff() throws Exception {
        try (ThreadedRun run = new ThreadedRun(LocalEnvironment.root().resolve("testLoadFiles/environment/empty-room.xml"),
                1, 600)) {
            Future<Ran> r1 = run.robot(() -> run(RobotConnectionCallbacks::main, "r1", "127.0.0.1",
                    String.valueOf(run.port())));
            Future<Ran> r2 = run.robot(() -> run(RobotConnectionCallbacks::main, "r2", "127.0.0.1",
                    String.valueOf(run.port())));
            Ran ran = r1.get(90, TimeUnit.SECONDS);
            r2.get(90, TimeUnit.SECONDS);
            RunReport report = run.await();
            // the connect callback first, then the program; stopRunning disconnects, and the
            // disconnect callback exits 0 before the program's own exit
            assertTrue(ran.out().startsWith("Connecting robot r1 to the RoboSim Environment at 127.0.0.1:"), ran.out());
            // ARIA's lines as it connects and disconnects, as the C++ prints them over a Pioneer port
            assertTrue(ran.out().contains("Connected to robot.\nName: r1\nType: Pioneer\nSubtype: p3dx\n"
                    + "Using default parameters for a p3dx robot\n"
                    + "Robot Serial Number: SIM\nConnHandler: Connected. Turning off sonar,\n"
                    + "ArRobotConnector: Connected to simulator, not connecting to additional hardware components.\n"
                    + "robotConnectionCallbacks: Connected.\nSleeping for 10 seconds...\n...requesting that the robot"
                    + " thread exit, then shutting down ARIA and exiting.\nDisconnecting from robot.\n"
                    + "ConnHandler: Connection closed. Exiting the program.\n"), ran.out());
            assertEquals(0, ran.exit(), ran.out());
            assertTrue(report.steps() >= 100 && report.steps() < 115, "10 s of 100 ms steps: " + report.steps());
        }
    }

    @Test
    void robotSyncTaskExamplesTaskPrintsTheStateEveryCycleUntilTheRunEnds() throws Exception {
        try (ThreadedRun run = new ThreadedRun(LocalEnvironment.root().resolve("testLoadFiles/environment/empty-room.xml"),
                1, 50)) {
            java.io.ByteArrayOutputStream printed = new java.io.ByteArrayOutputStream();
            Future<Ran> r1;
            Future<Ran> r2;
            java.io.PrintStream out = System.out;
            synchronized (System.class) {
                System.setOut(new PrintStream(printed, true, StandardCharsets.UTF_8));
                try {
                    r1 = run.robot(() -> run(RobotSyncTaskExample::main, "r1", "127.0.0.1", String.valueOf(run.port())));
                    r2 = run.robot(() -> run(RobotSyncTaskExample::main, "r2", "127.0.0.1", String.valueOf(run.port())));
                    run.await();
                    r1.get(60, TimeUnit.SECONDS);
                    r2.get(60, TimeUnit.SECONDS);
                } finally {
                    System.setOut(out);
                }
            }
            String text = printed.toString(StandardCharsets.UTF_8);
            // a line each cycle for each robot (r1 at 1500, 1500, 45°; r2 at 4500, 4500, -135°), then the goodbyes
            assertTrue(text.contains("\rx 1500.0  y 1500.0  th    45.0 vel     0.0 mpacs"), text);
            assertTrue(text.contains("\rx 4500.0  y 4500.0  th  -135.0 vel     0.0 mpacs"), text);
            assertTrue(text.split("\r").length > 60, "a line a cycle, 50 steps each: " + text.split("\r").length);
            assertEquals(2, text.split("Disconnected. Goodbye.", -1).length - 1, text);
        }
    }

    @Test
    void lineFinderExampleSavesTheWallItSeesWhenFIsPressed() throws Exception {
        PioneerRun.room(dir);
        // ARIA's line finder writes 'points' and 'lines' to the working directory
        Path points = Path.of("points");
        Path lines = Path.of("lines");
        java.nio.file.Files.deleteIfExists(points);
        java.nio.file.Files.deleteIfExists(lines);
        try (ThreadedRun run = new ThreadedRun(dir.resolve("room.xml"), 1, 30)) {
            Future<Ran> r1 = run.robot(() -> runWithInput(keysOnceTheLaserHasReadings("f"), LineFinderExample::main,
                    "r1", "127.0.0.1", String.valueOf(run.port()), "-connectLaser"));
            run.await();
            Ran ran = r1.get(60, TimeUnit.SECONDS);
            assertEquals(0, ran.exit(), ran.out());
            assertTrue(ran.out().contains("lineFinderExample: Connected to laser\n"), ran.out());
            assertTrue(ran.out().contains("Saved points and lines\n"), ran.out());
            // r1 at (3000, 3000) faces +x in a room whose inner faces are at 100 and 9900: within the
            // line finder's 5 m, only the wall on the right, y = 100, from about x = 3000 to 7073
            java.util.List<double[]> p = numbers(points);
            java.util.List<double[]> l = numbers(lines);
            assertTrue(p.size() > 40, "points: " + p.size());
            assertTrue(p.stream().allMatch(xy -> Math.abs(xy[1] - 100) <= 2 && xy[0] > 2900 && xy[0] < 7100),
                    () -> "points off the wall: " + java.util.Arrays.deepToString(p.toArray()));
            assertTrue(!l.isEmpty(), "lines: none");
            assertTrue(l.stream().allMatch(xyd -> Math.abs(xyd[1] - 100) <= 2 && Math.abs(xyd[3]) <= 2
                    && Math.abs(xyd[2]) > 1000), () -> "lines: " + java.util.Arrays.deepToString(l.toArray()));
        } finally {
            java.nio.file.Files.deleteIfExists(points);
            java.nio.file.Files.deleteIfExists(lines);
        }
    }

    @Test
    void threadExampleCountsInItsThreadWaitsOnTheConditionAndStopsTheThread() {
        java.io.ByteArrayOutputStream printed = new java.io.ByteArrayOutputStream();
        Ran ran;
        java.io.PrintStream out = System.out;
        synchronized (System.class) {
            System.setOut(new PrintStream(printed, true, StandardCharsets.UTF_8));
            try {
                ran = run(ThreadExample::main);
            } finally {
                System.setOut(out);
            }
        }
        String log = ran.out();
        // the counter reaches 10 and signals; the main thread, polling every 600 ms, sees 10 after
        // the signal, so (a signal with nobody waiting being lost, as in ARIA) the signal at 20 wakes it
        assertTrue(log.startsWith("Main thread: Running new example thread ...\n"), log);
        assertTrue(log.contains("Example thread: incremented counter to 10.\nExample thread: Signalling condition.\n"), log);
        assertTrue(printed.toString(StandardCharsets.UTF_8).contains("Main thread: Counter=10.\n"), printed::toString);
        int waiting = log.indexOf("Main thread: Waiting on condition object...");
        int woken = log.indexOf(" ExampleThreadCondition ArCondition object was signalled, done waiting for it.");
        assertTrue(waiting > 0 && woken > waiting, log);
        assertTrue(log.lastIndexOf("Example thread: Signalling condition.") < woken, log);
        assertTrue(log.contains("Main thread: Condition was signaled, and execution continued. Telling the other thread"
                + " to stop running.\nMain thread: Waiting for the other thread to exit, then exiting the program.\n"), log);
        assertTrue(log.contains("Main thread: Exiting program.\n"), log);
    }

    /**
     * Keys pressed once the program's robot has a laser scan, as a user presses them: the key
     * handler's reader, a thread of the program's, waits (bounded) for the robot's first laser to
     * have readings before it reads the keys.
     */
    static java.io.InputStream keysOnceTheLaserHasReadings(String keys) {
        byte[] bytes = keys.getBytes(StandardCharsets.ISO_8859_1);
        return new java.io.InputStream() {
            private int next = -1;

            @Override
            public int read() throws java.io.IOException {
                if (next < 0) {
                    long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
                    while (Aria.getRobotList().stream().map(r -> r.findLaser(1))
                            .noneMatch(l -> l != null && !l.getRawReadings().isEmpty())) {
                        if (System.nanoTime() > end) {
                            throw new java.io.IOException("the robot's laser had no readings within 60 s");
                        }
                        try {
                            Thread.sleep(5);
                        } catch (InterruptedException e) {
                            Thread.currentThread().interrupt();
                            throw new java.io.InterruptedIOException();
                        }
                    }
                    next = 0;
                }
                return next < bytes.length ? bytes[next++] & 0xff : -1;
            }
        };
    }

    /** The numbers of each line of a file the line finder wrote. */
    private static java.util.List<double[]> numbers(Path file) throws java.io.IOException {
        return java.nio.file.Files.readAllLines(file).stream()
                .map(line -> java.util.Arrays.stream(line.trim().split(" ")).mapToDouble(Double::parseDouble).toArray())
                .toList();
    }
}
