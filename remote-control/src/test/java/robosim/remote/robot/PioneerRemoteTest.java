package robosim.remote.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.params.RobotParameterFiles;
import robosim.remote.LiveEnvironment;
import robosim.remote.MessageDraft;
import robosim.remote.Readings;

/** A Pioneer driven through {@link PioneerRemote} in a live Environment, without a window. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class PioneerRemoteTest {
    static final String ROOM = """
            <?xml version="1.0" encoding="UTF-8"?>
            <world name="room" width="6000" height="6000" stepMs="100" boundary="true">
              <robot name="r1" type="pioneer" x="1500" y="3000" th="0" params="%ROBOTS%/p3dx.p"/>
              <robot name="r2" type="pioneer" x="4500" y="3000" th="180" params="%ROBOTS%/p3dx.p"/>
            </world>
            """;

    @TempDir
    Path dir;
    private LiveEnvironment env;
    private final Thread[] threads = new Thread[2];
    private final PioneerRemote[] robots = new PioneerRemote[2];

    /** Connects r1 and r2, each on a thread of its own that then runs it, as the RemoteControl does. */
    private void start() throws Exception {
        env = new LiveEnvironment(dir, ROOM);
        for (int i = 0; i < 2; i++) {
            int n = i;
            threads[i] = new Thread(() -> {
                PioneerRemote r = PioneerRemote.connect("r" + (n + 1), "127.0.0.1", env.robotPort(),
                        RobotParameterFiles.load("p3dx"));
                robots[n] = r;
                r.run();
            }, "r" + (i + 1));
            threads[i].start();
        }
        assertTrue(LiveEnvironment.await(() -> robots[0] != null && robots[1] != null
                && robots[0].latest() != null && robots[1].latest() != null, 20_000), "both robots are running");
    }

    @AfterEach
    void stop() throws Exception {
        for (int i = 0; i < 2; i++) {
            if (robots[i] != null) {
                robots[i].disconnect();
            }
            if (threads[i] != null) {
                threads[i].join(10_000);
            }
        }
        if (env != null) {
            env.close();
        }
    }

    @Test
    void driveMovesTheRobotAndItsReadingsSayHowFast() throws Exception {
        start();
        robots[0].drive(300, 0);
        assertTrue(LiveEnvironment.await(() -> robots[0].latest().vel() > 250, 5_000), "speeds up");
        assertTrue(LiveEnvironment.await(() -> env.robot("r1").x() > 1700, 5_000), "moved in the world");
        robots[0].stop();
        assertTrue(LiveEnvironment.await(() -> robots[0].latest().vel() == 0, 5_000), "stops");
    }

    @Test
    void theSonarRingIsReadAndCanBeSwitchedOff() throws Exception {
        start();
        assertTrue(LiveEnvironment.await(() -> robots[0].latest().sonar().size() == 16, 5_000), "16 sonar rays");
        robots[0].sonar(false);
        assertTrue(LiveEnvironment.await(() -> !robots[0].latest().sonarOn(), 5_000));
        assertEquals(0, robots[0].latest().sonar().size());
    }

    @Test
    void theLaserSeesTheOtherRobotAheadOnceSwitchedOn() throws Exception {
        start();
        assertFalse(robots[0].latest().laserOn());
        assertEquals(null, robots[0].laser(true));
        assertTrue(LiveEnvironment.await(() -> robots[0].latest().laser().stream()
                .anyMatch(p -> Math.abs(p.y()) < 100 && p.x() > 2500 && p.x() < 3000), 5_000), "r2 is 3 m ahead");
    }

    @Test
    void theHeatSensorReadsOnceSwitchedOn() throws Exception {
        start();
        assertEquals(null, robots[0].heat(true));
        assertTrue(LiveEnvironment.await(() -> robots[0].latest().heat() != null, 5_000));
        Readings.Heat h = robots[0].latest().heat();
        assertEquals(0, h.intensity(), "the room has no heat source");
    }

    @Test
    void aMessageSentToARobotArrivesInItsInbox() throws Exception {
        start();
        robots[0].send(MessageDraft.of(MessageDraft.To.ROBOT, "r2", "hello r2"));
        assertTrue(LiveEnvironment.await(() -> robots[1].inbox().total() == 1, 5_000));
        String line = robots[1].inbox().lines().get(0);
        assertTrue(line.matches("step \\d+, from r1 to r2: hello r2"), line);
    }

    @Test
    void aRobotTheWorldDoesNotNameCannotConnect() throws Exception {
        env = new LiveEnvironment(dir, ROOM);
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> PioneerRemote.connect("r9", "127.0.0.1", env.robotPort(), RobotParameterFiles.load("p3dx")));
        assertTrue(e.getMessage().startsWith("robot r9 could not connect to 127.0.0.1:" + env.robotPort() + ": "),
                e.getMessage());
        assertNotNull(e.getMessage());
    }
}
