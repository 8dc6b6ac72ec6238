package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.env.net.ServerOptions;
import robosim.protocol.ControlReply;
import robosim.protocol.LogLine;
import robosim.protocol.Message;

/** The {@code log} control request: the Environment's log lines reach the control client that follows them. */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class LogFollowTest {
    private final ExecutorService threads = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "scripted-robot");
        t.setDaemon(true);
        return t;
    });

    @AfterEach
    void stopRobots() {
        threads.shutdownNow();
    }

    @Test
    void aFollowerIsSentTheLinesOfRobotsJoiningAndOfRequestsCarriedOut() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback());
             ControlPeer follower = new ControlPeer(h.viewerPort(), "panel");
             ControlPeer control = new ControlPeer(h.viewerPort(), "ctl")) {
            ControlReply answer = follower.ask("log");
            assertTrue(answer.ok(), answer.text());
            assertEquals("following the Environment's log from step 0", answer.text());
            control.send("pause");
            threads.submit(new ScriptedRobot(h.robotPort(), "r1", h.sim.world().robots().get(0).parameters(), false));
            threads.submit(new ScriptedRobot(h.robotPort(), "r2", h.sim.world().robots().get(1).parameters(), false));
            assertEquals("paused after step 0", control.reply().text());
            control.ask("remove", "r2");

            List<String> lines = new ArrayList<>();
            while (lines.stream().noneMatch(l -> l.contains("removed robot r2"))) {
                Message m = follower.peer.read();
                if (m instanceof LogLine l) {
                    lines.add(l.level() + " " + l.text());
                }
            }

            assertTrue(lines.stream().anyMatch(l -> l.startsWith("INFO ") && l.contains("robot r1 connected")), lines::toString);
            assertTrue(lines.stream().anyMatch(l -> l.contains("control client ctl removed robot r2 after step 0")),
                    lines::toString);
        }
    }

    @Test
    void aClientThatDoesNotAskIsSentNoLogLines() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback());
             ControlPeer control = new ControlPeer(h.viewerPort(), "ctl")) {
            control.send("pause");
            threads.submit(new ScriptedRobot(h.robotPort(), "r1", h.sim.world().robots().get(0).parameters(), false));
            threads.submit(new ScriptedRobot(h.robotPort(), "r2", h.sim.world().robots().get(1).parameters(), false));

            // reply() fails on any message but an answer, a log line among them
            assertEquals("paused after step 0", control.reply().text());
            assertEquals("ran 2 steps; paused after step 2", control.ask("step", "2").text());
            assertFalse(control.ask("log", "now").ok());
        }
    }
}
