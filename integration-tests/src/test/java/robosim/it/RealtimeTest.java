package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.aria.ArRobot;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.examples.wander.Wander;

/** In real time, step n starts no earlier than (n − 1) × stepMs after the first. */
@Timeout(value = 1, unit = TimeUnit.MINUTES)
class RealtimeTest {
    @Test
    void realtimeStepsAreNotFasterThanTheStepLength() throws Exception {
        ServerOptions realtime = new ServerOptions("127.0.0.1", 0, 0, 8, true, 10_000, 30_000, 0, 4 << 20);
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", realtime)) {
            for (String name : List.of("r1", "r2")) {
                Thread t = new Thread(() -> {
                    ArRobot robot = new ArRobot(name, "127.0.0.1", h.server.robotPort(), "p3dx");
                    if (robot.blockingConnect()) {
                        robot.enableMotors();
                        new Wander(robot).run();
                    }
                });
                t.setDaemon(true);
                t.start();
            }
            RunReport report = h.await();
            assertEquals(8, report.steps());
            assertTrue(report.wallNanos() >= TimeUnit.MILLISECONDS.toNanos(700),
                    "8 steps of 100 ms: the 8th starts 700 ms after the first, took " + report.wallNanos() / 1e6 + " ms");
        }
    }
}
