package robosim.remote.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.params.RobotParameterFiles;
import robosim.remote.LiveEnvironment;

/** A Scout driven through {@link ScoutRemote} in a live Environment, without a window. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class ScoutRemoteTest {
    private static final String ROOM = """
            <?xml version="1.0" encoding="UTF-8"?>
            <world name="room" width="6000" height="6000" stepMs="100" boundary="true">
              <robot name="s1" type="scout" x="1500" y="3000" th="0" params="%ROBOTS%/scout.p"/>
            </world>
            """;

    @TempDir
    Path dir;
    private LiveEnvironment env;
    private Thread thread;
    private volatile ScoutRemote scout;

    @BeforeEach
    void start() throws Exception {
        env = new LiveEnvironment(dir, ROOM);
        thread = new Thread(() -> {
            ScoutRemote s = ScoutRemote.connect("s1", "127.0.0.1", env.robotPort(), RobotParameterFiles.load("scout"));
            scout = s;
            s.run();
        }, "s1");
        thread.start();
        assertTrue(LiveEnvironment.await(() -> scout != null && scout.latest() != null, 20_000), "the Scout runs");
    }

    @AfterEach
    void stop() throws Exception {
        if (scout != null) {
            scout.disconnect();
        }
        thread.join(10_000);
        env.close();
    }

    @Test
    void driveMovesTheScoutForwardInMillimetres() throws Exception {
        scout.drive(200, 0);
        assertTrue(LiveEnvironment.await(() -> Math.abs(scout.latest().vel() - 200) < 5, 5_000), "200 mm/s: "
                + scout.latest());
        assertTrue(LiveEnvironment.await(() -> env.robot("s1").x() > 1650, 5_000), "moved in the world");
        scout.stop();
        assertTrue(LiveEnvironment.await(() -> scout.latest().vel() == 0, 5_000), "stops");
    }

    @Test
    void turningReadsAsDegreesPerSecond() throws Exception {
        scout.drive(0, 30);
        assertTrue(LiveEnvironment.await(() -> Math.abs(scout.latest().rotVel() - 30) < 1.5, 5_000), "30 deg/s: "
                + scout.latest());
    }

    @Test
    void setHeadingTurnsToTheHeading() throws Exception {
        scout.setHeading(90);
        assertTrue(LiveEnvironment.await(() -> Math.abs(env.robot("s1").th() - 90) < 3
                && scout.latest().rotVel() == 0, 10_000), "faces north: " + env.robot("s1"));
    }

    @Test
    void theScoutHasNoLaserAndNoHeatSensor() {
        assertEquals("a Scout has no laser", scout.laser(true));
        assertEquals("a Scout has no heat sensor", scout.heat(true));
        assertNull(scout.laser(false));
    }

    @Test
    void itsSonarsAreReadAndCanBeSwitchedOff() throws Exception {
        assertTrue(LiveEnvironment.await(() -> scout.latest().sonar().size() == 16, 5_000));
        scout.sonar(false);
        assertTrue(LiveEnvironment.await(() -> scout.latest().sonar().isEmpty() && !scout.latest().sonarOn(), 5_000));
    }
}
