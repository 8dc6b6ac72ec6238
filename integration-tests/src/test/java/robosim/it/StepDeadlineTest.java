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
        ServerOptions options = new ServerOptions("127.0.0.1", 0, 0, STEPS, false, 500, 30_000, 0, 4 << 20);
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

    private static RobotSummary summary(RunReport report, String name) {
        return report.robots().stream().filter(r -> r.name().equals(name)).findFirst().orElseThrow();
    }
}
