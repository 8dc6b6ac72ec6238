package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.aria.ArRobot;
import robosim.aria.ArUtil;
import robosim.env.net.ServerOptions;
import robosim.hw.RobotMessage;
import robosim.cli.Background;

/** Robot-side messaging over TCP: objects and text, a blocking receive in simulated time, errors. */
@Timeout(value = 1, unit = TimeUnit.MINUTES)
class MessagingEndToEndTest {
    /** A payload sent as JSON. */
    public record Waypoint(String label, double x, double y) { }

    /** What r2 saw. */
    record Seen(Waypoint first, String text, long waitedSteps, boolean timedOut, String error) { }

    @Test
    void robotsTalkThroughTheEnvironment() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback().withMaxSteps(40))) {
            CompletableFuture<Void> sender = Background.run("robot r1", () -> {
                ArRobot r1 = new ArRobot("r1", "127.0.0.1", h.server.robotPort(), "p3dx");
                r1.blockingConnect();
                ArUtil.sleep(500);
                r1.send("r2", new Waypoint("door", 1200.5, 3400));
                r1.broadcast("after the waypoint");
                r1.waitForRunExit();
            });
            CompletableFuture<Seen> receiver = Background.supply("robot r2", () -> {
                ArRobot r2 = new ArRobot("r2", "127.0.0.1", h.server.robotPort(), "p3dx");
                r2.blockingConnect();
                long before = r2.getStep();
                RobotMessage first = r2.receive(5000);
                long waited = r2.getStep() - before;
                RobotMessage second = r2.receive(5000);
                long start = r2.getStep();
                RobotMessage none = r2.receive(300);
                boolean timedOut = none == null && r2.getStep() - start == 3;
                r2.send("nobody", "hello?");
                ArUtil.sleep(200);
                String error = r2.pollRequestError();
                Seen s = new Seen(first.as(Waypoint.class), second.text(), waited, timedOut, error);
                r2.waitForRunExit();
                return s;
            });
            Seen s = receiver.get(30, TimeUnit.SECONDS);
            h.await();
            sender.get(10, TimeUnit.SECONDS);
            assertEquals(new Waypoint("door", 1200.5, 3400), s.first());
            assertEquals("after the waypoint", s.text());
            assertEquals(6, s.waitedSteps(), "sent after 500 ms (step 6), received with the state after step 6");
            assertTrue(s.timedOut(), "a receive with nothing to come waits 300 simulated ms, 3 steps");
            assertTrue(s.error() != null && s.error().contains("'nobody'"), String.valueOf(s.error()));
        }
    }
}
