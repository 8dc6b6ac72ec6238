package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.aria.ArRobot;
import robosim.env.core.RobotSummary;
import robosim.env.net.Departure;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.examples.wander.Wander;
import robosim.hw.RunEnd;

/**
 * A robot whose code never yields misses the step deadline: the Environment drops it by name with
 * one log line and the run goes on for the others, instead of waiting for it forever.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class StepDeadlineTest {
    private static final int STEPS = 40;

    @Test
    void aRobotThatNeverYieldsIsDroppedByNameAndTheRunReachesItsSteps() throws Exception {
        // the first steps' allowance as short as the step timeout: r2 never yields at all
        ServerOptions options = new ServerOptions("127.0.0.1", 0, 0, STEPS, false, 500, 30_000, 0, 4 << 20)
                .withFirstStepsTimeoutMs(500);
        AtomicBoolean spinning = new AtomicBoolean(true);
        AtomicBoolean r2Connected = new AtomicBoolean();
        AtomicBoolean r2SawItsEnd = new AtomicBoolean();
        AtomicReference<RunEnd> r2End = new AtomicReference<>();
        Thread r1 = null;
        Thread r2 = null;
        try (LogCapture log = new LogCapture("robosim.env.net");
             LocalEnvironment h = new LocalEnvironment("empty-room.xml", options)) {
            r1 = new Thread(() -> {
                ArRobot robot = new ArRobot("r1", "127.0.0.1", h.server.robotPort(), "p3dx");
                if (robot.blockingConnect()) {
                    robot.enableMotors();
                    new Wander(robot).run();
                }
            }, "robot-r1");
            r2 = new Thread(() -> {
                ArRobot robot = new ArRobot("r2", "127.0.0.1", h.server.robotPort(), "p3dx");
                if (robot.blockingConnect()) {
                    robot.enableMotors();
                    r2Connected.set(true);
                    robot.setVel(200);
                    AtomicLong work = new AtomicLong();
                    while (spinning.get() && robot.isConnected()) {
                        work.incrementAndGet(); // busy computing, never yielding to the simulation
                    }
                    r2SawItsEnd.set(!robot.isConnected());
                    r2End.set(robot.getRunEnd());
                }
            }, "robot-r2");
            for (Thread t : List.of(r1, r2)) {
                t.setDaemon(true);
                t.start();
            }

            RunReport report = h.await();

            assertTrue(r2Connected.get(), "r2 connected before the run started");
            assertEquals("step limit " + STEPS + " reached", report.endReason(), "the run went on without r2");
            assertEquals(STEPS, report.steps());
            RobotSummary r1Summary = summary(report, "r1");
            assertTrue(r1Summary.distance() > 100, "r1 kept driving: " + r1Summary);
            List<String> aboutR2 = log.warnings().stream().filter(w -> w.contains("robot r2")).toList();
            assertEquals(1, aboutR2.size(), "one log line for r2: " + log.warnings());
            assertTrue(aboutR2.get(0).contains("did not send its requests for step"), aboutR2.get(0));
            assertTrue(aboutR2.get(0).contains("(env --step-timeout gives it longer)"), aboutR2.get(0));
            assertTrue(log.warnings().stream().noneMatch(w -> w.contains("robot r1")), "r1 was not dropped: "
                    + log.warnings());
            assertEquals(Departure.Kind.DROPPED, report.departure("r2").orElseThrow().kind(), "the report marks r2");
            r2.join(10_000);
            assertTrue(r2SawItsEnd.get(), "r2's program learnt that the Environment dropped it");
            assertEquals(RunEnd.Kind.DROPPED, r2End.get().kind(), "and why: " + r2End.get());
        } finally {
            spinning.set(false);
            for (Thread t : new Thread[] {r1, r2}) {
                if (t != null) {
                    t.join(10_000);
                    assertFalse(t.isAlive(), t.getName() + " has stopped");
                }
            }
        }
    }

    /**
     * A robot whose first step takes longer than the step timeout (its program loading classes on a
     * busy machine) stays in the run: its first {@value ServerOptions#FIRST_STEPS} steps wait up to
     * the first steps' timeout. The same delay later is a missed deadline.
     */
    @Test
    void aSlowFirstStepIsWaitedForButTheSameDelayLaterDropsTheRobot() throws Exception {
        ServerOptions options = new ServerOptions("127.0.0.1", 0, 0, STEPS, false, 1000, 30_000, 0, 4 << 20)
                .withFirstStepsTimeoutMs(60_000);
        try (LogCapture log = new LogCapture("robosim.env.net");
             LocalEnvironment h = new LocalEnvironment("empty-room.xml", options)) {
            List<Thread> robots = new java.util.ArrayList<>();
            for (String name : List.of("r1", "r2")) {
                Thread t = new Thread(() -> {
                    ArRobot robot = new ArRobot(name, "127.0.0.1", h.robotPort(), "p3dx");
                    if (robot.blockingConnect()) {
                        robot.enableMotors();
                        // step 1: busy for three step timeouts before the first yield
                        busy(2500);
                        for (int step = 2; robot.isConnected(); step++) {
                            robot.sleepSimulated(100);
                            if (name.equals("r2") && step == 10) {
                                busy(2500); // the same delay in step 10: no allowance now
                            }
                        }
                    }
                }, "slow-" + name);
                t.setDaemon(true);
                t.start();
                robots.add(t);
            }
            RunReport report = h.await();
            assertEquals("step limit " + STEPS + " reached", report.endReason());
            assertTrue(report.departure("r1").isEmpty(), "r1's slow first step was waited for: " + log.warnings());
            Departure r2 = report.departure("r2").orElseThrow();
            assertEquals(Departure.Kind.DROPPED, r2.kind());
            assertTrue(r2.step() >= 10, "r2 was dropped for its slow step 10, not its first: " + r2);
            for (Thread t : robots) {
                t.join(10_000);
            }
        }
    }

    /** Works on this thread, without yielding to the simulation, for about this many ms of wall time. */
    private static void busy(long ms) {
        long until = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(ms);
        while (System.nanoTime() - until < 0) {
            Thread.onSpinWait();
        }
    }

    private static RobotSummary summary(RunReport report, String name) {
        return report.robots().stream().filter(r -> r.name().equals(name)).findFirst().orElseThrow();
    }
}
