package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArActionGotoStraight;
import robosim.aria.ArRobot;
import robosim.aria.ArUtil;
import robosim.cli.Background;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.examples.aria.ActionGroupExample;
import robosim.examples.aria.GotoActionExample;
import robosim.examples.aria.SingleThreadLoopExample;
import robosim.it.AriaExamplesTest.Ran;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.SnapshotListener;

/**
 * More of AriaCoda's examples ported to Java ({@code examples/aria}): singleThreadLoopExample,
 * actionGroupExample and gotoActionExample, each run against a RoboSim Environment in lockstep and
 * checked for what it is meant to do.
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class AriaExamplesMoreTest {
    private static final Pattern POSE = Pattern.compile(
            "singleThreadExample: Pose=\\((-?[\\d.]+),(-?[\\d.]+),(-?[\\d.]+)\\), Trans\\.  Vel=(-?[\\d.]+), Battery=");

    @TempDir
    Path dir;

    /** Runs an example as {@link AriaExamplesTest#run} does, with this standard input and its standard output kept. */
    static Ran runWithStdio(InputStream in, ByteArrayOutputStream out, Consumer<String[]> main, String... args) {
        synchronized (System.class) {
            InputStream oldIn = System.in;
            PrintStream oldOut = System.out;
            System.setIn(in);
            System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
            try {
                return AriaExamplesTest.run(main, args);
            } finally {
                System.setIn(oldIn);
                System.setOut(oldOut);
            }
        }
    }

    @Test
    void singleThreadLoopRunsTheCycleFromItsOwnLoopAndPrintsEachTimeRound() throws Exception {
        PioneerRun.room(dir);
        try (ThreadedRun run = new ThreadedRun(dir.resolve("room.xml"), 1, 100)) {
            Future<Ran> r1 = run.robot(() -> AriaExamplesTest.run(SingleThreadLoopExample::main, "r1", "127.0.0.1",
                    String.valueOf(run.port())));
            RunReport report = run.await();
            Ran ran = r1.get(60, TimeUnit.SECONDS);
            assertEquals(0, ran.exit(), ran.out());
            assertTrue(ran.out().contains("singleThreadExample: Connected to robot.\n"), ran.out());
            List<double[]> poses = new ArrayList<>();
            Matcher m = POSE.matcher(ran.out());
            while (m.find()) {
                poses.add(new double[] {Double.parseDouble(m.group(1)), Double.parseDouble(m.group(2)),
                        Double.parseDouble(m.group(3)), Double.parseDouble(m.group(4))});
            }
            // one cycle a step: each loop takes no simulated time and sleeps one step
            long quick = ran.out().lines().filter(l -> l.equals("singleThreadExample: loop took 0 ms, sleeping 20 ms"))
                    .count();
            assertEquals(poses.size(), quick, ran.out());
            assertTrue(!ran.out().contains("warning"), ran.out());
            assertEquals(100, report.steps());
            assertEquals(100, poses.size(), "a loop a step");
            // the first loop before any step: where it connected, no state of charge yet (as ARIA's first)
            assertTrue(ran.out().contains("singleThreadExample: Connected to robot.\nsingleThreadExample:"
                    + " Pose=(3000.00,3000.00,0.00), Trans.  Vel=0.00, Battery=13.00V\n"), ran.out());
            // then each loop one step further round at 300 mm/s, 10 deg/s: 30 mm and 1 degree a loop
            double[] last = poses.get(poses.size() - 1);
            double[] before = poses.get(poses.size() - 2);
            assertEquals(300, last[3], 0.5, "velocity");
            assertEquals(1.0, last[2] - before[2], 0.02, "a degree a step");
            assertEquals(30, Math.hypot(last[0] - before[0], last[1] - before[1]), 0.1, "30 mm a step");
            // the rotation is at full speed at once, the velocity ramps up (30 mm/s a step), so the
            // arc starts tighter than the circle of 1719 mm it goes on along: 9.5 s at 300 mm/s in all
            RobotSummary r = report.robots().get(0);
            assertEquals(2850, r.distance(), 1, "distance: " + r);
            assertEquals(99.5, r.th(), 0.1, "heading: " + r);
            assertEquals(4560.6, r.x(), 1, "x: " + r);
            assertEquals(4995.1, r.y(), 1, "y: " + r);
        }
    }

    @Test
    void singleThreadLoopRunsACycleASipThroughThePioneerPort() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), 30, false, code -> { })) {
            Ran ran = Background.supply("singleThreadLoopExample", () -> AriaExamplesTest.run(
                    SingleThreadLoopExample::main, "-rh", "127.0.0.1", "-rrtp", String.valueOf(run.ports.portOf("r1"))))
                    .get(90, TimeUnit.SECONDS);
            assertEquals(0, ran.exit(), ran.out());
            List<String> poses = ran.out().lines().filter(l -> l.startsWith("singleThreadExample: Pose=")).toList();
            // the odometry starts at the origin; each loop sleeps until the next SIP, so each sees a new
            // pose, but for the port's real-time pacing: a SIP before the motion starts and the run's end
            // may each come a loop late, and that loop prints the pose before again
            assertTrue(poses.get(0).startsWith("singleThreadExample: Pose=(0.00,0.00,0.00), Trans.  Vel=0.00"), ran.out());
            assertTrue(poses.stream().distinct().count() >= poses.size() - 2, "a new state each loop: " + ran.out());
            // 30 steps, each a SIP, and the SIP the connection starts with; a loop the pacing makes
            // late may see one more
            assertTrue(poses.size() >= 20 && poses.size() <= 32, "a loop a SIP: " + poses.size());
        }
    }

    @Test
    void loopOnceRunsTheCycleOnTheCallersThreadOncePerCallAndNotBetween() throws Exception {
        PioneerRun.room(dir);
        try (ThreadedRun run = new ThreadedRun(dir.resolve("room.xml"), 1, 0)) {
            List<String> ran = new ArrayList<>();
            Future<long[]> program = run.robot(() -> {
                ArRobot robot = new ArRobot("r1", "127.0.0.1", run.port(), "p3dx");
                assertTrue(robot.blockingConnect(), robot.getConnectionError());
                robot.addUserTask("note", 50, () -> ran.add(Thread.currentThread().getName() + " "
                        + robot.getCounter() + " " + robot.getLastPacketTime().getTimeMs()));
                String me = Thread.currentThread().getName();
                long counter = robot.getCounter();
                long start = new robosim.aria.ArTime().getTimeMs();
                for (int i = 0; i < 10; i++) {
                    robot.loopOnce();
                    ArUtil.sleep(20);
                }
                int inLoop = ran.size();
                ArUtil.sleep(500); // no loopOnce: no cycle
                long[] out = {counter, robot.getCounter(), inLoop, ran.size(), start,
                        me.equals("robot-program") ? 1 : 0};
                robot.disconnect();
                return out;
            });
            long[] out = program.get(60, TimeUnit.SECONDS);
            run.await();
            // the first call runs the cycle at once, on the state the robot has; each loop after is one step
            assertEquals(10, out[2], ran.toString());
            assertEquals(10, out[3], "no cycle without loopOnce: " + ran);
            assertEquals(out[0] + 10, out[1], "one count a call");
            for (int i = 0; i < 10; i++) {
                assertEquals("robot-program " + (out[0] + i) + " " + (out[4] + 100 * i), ran.get(i), ran.toString());
            }
        }
    }

    @Test
    void actionGroupExampleSwitchesBetweenTeleopAndWanderOnTheKeys() throws Exception {
        PioneerRun.room(dir);
        List<Snapshot> snapshots = new ArrayList<>();
        SnapshotListener keep = new SnapshotListener() {
            @Override
            public void world(WorldDescription w) {
            }

            @Override
            public void snapshot(Snapshot f) {
                synchronized (snapshots) {
                    snapshots.add(f);
                }
            }
        };
        // w after step 20, t after 70, four UP arrows after 100, Escape after 140
        try (SteppedKeys keys = new SteppedKeys(Map.of(20L, "w", 70L, "t", 100L, "\u001b[A\u001b[A\u001b[A\u001b[A",
                140L, "\u001b"));
             LocalEnvironment env = new LocalEnvironment(WorldReader.read(dir.resolve("room.xml")), 1,
                     ServerOptions.loopback().withMaxSteps(400), keep, keys)) {
            ByteArrayOutputStream printed = new ByteArrayOutputStream();
            Future<Ran> r1 = Background.supply("actionGroupExample", () -> runWithStdio(keys, printed,
                    ActionGroupExample::main, "r1", "127.0.0.1", String.valueOf(env.robotPort())));
            Ran ran = r1.get(90, TimeUnit.SECONDS);
            RunReport report = env.await();
            String out = printed.toString(StandardCharsets.UTF_8);
            assertEquals(0, ran.exit(), ran.out());
            assertTrue(ran.out().contains("actionGroupExample: Connected to robot.\n"), ran.out());
            assertTrue(ran.out().contains("Escape was pressed, program is exiting."), ran.out());
            assertTrue(out.startsWith("Note: Do not have a joystick, only the arrow keys on the keyboard will work.\n"
                    + "\n== Teleoperation Mode ==\n"), out);
            int wanderAt = out.indexOf("== Wander Mode ==");
            int teleopAgain = out.indexOf("== Teleoperation Mode ==", wanderAt);
            assertTrue(wanderAt > 0 && teleopAgain > wanderAt, out);
            assertTrue(report.steps() > 140 && report.steps() < 150, "Escape ended it: " + report.steps());
            synchronized (snapshots) {
                // teleop, no key: still; wander: 400 mm/s; teleop again: stopped; four UPs: 100 mm/s
                assertEquals(0, speed(snapshots, 20), 0.5, "teleop, no keys");
                assertEquals(400, speed(snapshots, 70), 5, "wander");
                assertEquals(0, speed(snapshots, 100), 0.5, "teleop again");
                assertEquals(100, speed(snapshots, 140), 2, "four UPs");
            }
            // wander drove it straight along the room (nothing within the avoiding distances), then
            // teleop stopped it and the UPs drove it on: as AriaCoda's original over the Pioneer port
            // with the same keys at about the same times
            RobotSummary r = report.robots().get(0);
            assertEquals(0, r.collisions(), "collisions: " + r);
            assertEquals(2383.3, r.distance(), 1, "distance: " + r);
            assertEquals(5383.3, r.x(), 1, "x: " + r);
            assertEquals(3000, r.y(), 0.5, "y: " + r);
        }
    }

    /** @return the robot's speed over the step ending at {@code step}, mm/s */
    private static double speed(List<Snapshot> snapshots, long step) {
        Snapshot.RobotView a = view(snapshots, step - 1);
        Snapshot.RobotView b = view(snapshots, step);
        return Math.hypot(b.x() - a.x(), b.y() - a.y()) * 10;
    }

    private static Snapshot.RobotView view(List<Snapshot> snapshots, long step) {
        return snapshots.stream().filter(s -> s.step() == step).findFirst().orElseThrow().robots().get(0);
    }

    /** A square room about the origin, -2 m to 4.5 m each way, its robot r1 at (0, 0) facing +x. */
    static Path squareWorld(Path dir) throws Exception {
        Files.writeString(dir.resolve("square.map"), """
                2D-Map
                MinPos: -2000 -2000
                MaxPos: 4500 4500
                NumLines: 4
                LINES
                -2000 -2000 4500 -2000
                4500 -2000 4500 4500
                4500 4500 -2000 4500
                -2000 4500 -2000 -2000
                DATA
                """);
        return Files.writeString(dir.resolve("square.xml"), """
                <world name="square" stepMs="100">
                  <map file="square.map"/>
                  <robot name="r1" type="pioneer" x="0" y="0" th="0" params="%s"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p")));
    }

    @Test
    void gotoActionExampleDrivesTheSquareCornerByCornerForThirtySeconds() throws Exception {
        try (ThreadedRun run = new ThreadedRun(squareWorld(dir), 1, 0)) {
            Future<Ran> r1 = run.robot(() -> AriaExamplesTest.run(GotoActionExample::main, "r1", "127.0.0.1",
                    String.valueOf(run.port())));
            Ran ran = r1.get(120, TimeUnit.SECONDS);
            RunReport report = run.await();
            assertEquals(0, ran.exit(), ran.out());
            assertTrue(ran.out().contains("gotoActionExample: Connected to robot.\nGoing to four goals in turn for 30"
                    + " seconds, then cancelling goal and exiting.\nGoing to next goal at 2500 0\n"), ran.out());
            assertTrue(ran.out().contains("30 seconds have elapsed. Cancelling current goal, waiting 3 seconds, and"
                    + " exiting."), ran.out());
            List<String> goals = ran.out().lines().filter(l -> l.startsWith("Going to next goal at ")).toList();
            assertTrue(goals.size() >= 3, ran.out());
            String[] corners = {"2500 0", "2500 2500", "0 2500", "0 0"};
            for (int i = 0; i < goals.size(); i++) {
                assertEquals("Going to next goal at " + corners[i % 4], goals.get(i), ran.out());
            }
            // each goal but the last (cancelled) reached in turn, within ARIA's close distance (100 mm)
            double[][] at = {{2500, 0}, {2500, 2500}, {0, 2500}, {0, 0}};
            int reached = 0;
            synchronized (run.snapshots) {
                for (Snapshot s : run.snapshots) {
                    Snapshot.RobotView v = s.robots().get(0);
                    double[] c = at[reached % 4];
                    if (Math.hypot(v.x() - c[0], v.y() - c[1]) < ArActionGotoStraight.DEFAULT_CLOSE_DIST) {
                        reached++;
                    }
                }
            }
            assertEquals(4, goals.size(), ran.out());
            assertEquals(3, reached, "the fourth goal cancelled on its way: " + goals);
            // 33 s of steps, and the connection's; stopped 150 mm short of the start, where it was cancelled
            assertEquals(331, report.steps());
            RobotSummary r = report.robots().get(0);
            assertEquals(0, r.collisions(), "collisions: " + r);
            assertEquals(9971.5, r.distance(), 1, "distance: " + r);
            assertEquals(-7.8, r.x(), 1, "x: " + r);
            assertEquals(149.0, r.y(), 1, "y: " + r);
            assertEquals(-88, r.th(), 0.5, "heading: " + r);
            // each achieved as ARIA's says it, a little past the goal's distance and stopped
            assertEquals(3, ran.out().lines().filter(l -> l.matches("gotostraight: Achieved distance to goal"
                    + " \\(dist=-4\\.\\d\\d, robotVel=0\\.00\\)")).count(), ran.out());
        }
    }
}
