package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.aria.ArRobot;
import robosim.aria.ArUtil;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;

/**
 * One thread that connects two robots is the code of both, as in ARIA's twoRobotWander: while it
 * sleeps on one, the other's steps go on, in lockstep, and the run is the same each time.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class OneThreadTwoRobotsTest {
    private static List<Double> run() throws Exception {
        try (ThreadedRun run = new ThreadedRun(LocalEnvironment.root().resolve("testLoadFiles/environment/empty-room.xml"),
                1, 0)) {
            Future<Void> both = run.robot(() -> {
                ArRobot r1 = new ArRobot("r1", "127.0.0.1", run.port(), "p3dx");
                ArRobot r2 = new ArRobot("r2", "127.0.0.1", run.port(), "p3dx");
                assertTrue(r1.blockingConnect(), r1.getConnectionError());
                assertTrue(r2.blockingConnect(), r2.getConnectionError());
                r1.enableMotors();
                r2.enableMotors();
                r1.setVel(300);
                r2.setVel(200);
                ArUtil.sleep(2000); // on r2, the last connected: r1 goes on meanwhile
                r1.stop();
                ArUtil.sleep(1000);
                r1.disconnect();
                r2.disconnect();
                return null;
            });
            both.get(60, TimeUnit.SECONDS);
            RunReport report = run.await();
            RobotSummary r1 = report.robots().get(0);
            RobotSummary r2 = report.robots().get(1);
            return List.of(r1.distance(), r2.distance(), (double) report.steps());
        }
    }

    @Test
    void sleepingOnOneRobotLetsTheOthersStepsGoOnTheSameEachRun() throws Exception {
        List<Double> first = run();
        // r1 reaches 300 mm/s in 1 s at 300 mm/s² (150 mm), then 1 s at 300 mm/s, while the thread
        // sleeps on r2; r2 reaches 200 mm/s in 2/3 s (67 mm), then 2 1/3 s at 200 mm/s
        assertEquals(450, first.get(0), 40, "r1 drove while the thread slept on r2: " + first);
        assertEquals(533, first.get(1), 40, "r2: " + first);
        assertEquals(first, run(), "the same run again");
    }
}
