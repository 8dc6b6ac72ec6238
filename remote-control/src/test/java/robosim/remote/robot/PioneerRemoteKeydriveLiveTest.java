package robosim.remote.robot;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.params.RobotParameterFiles;
import robosim.remote.KeyDrive;
import robosim.remote.LiveEnvironment;

/** A Pioneer driven by its keydrive action in a live Environment, the key presses made from another thread as the window makes them. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class PioneerRemoteKeydriveLiveTest {
    @TempDir
    Path dir;
    private LiveEnvironment env;
    private final Thread[] threads = new Thread[2];
    private final PioneerRemote[] robots = new PioneerRemote[2];

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
    void upPressesDriveTheRobotForwardAndSpaceStopsIt() throws Exception {
        env = new LiveEnvironment(dir, PioneerRemoteTest.ROOM);
        for (int i = 0; i < 2; i++) {
            int n = i;
            threads[i] = new Thread(() -> {
                PioneerRemote r = PioneerRemote.connect("r" + (n + 1), "127.0.0.1", env.robotPort(),
                        RobotParameterFiles.load("p3dx"), n == 0);
                robots[n] = r;
                r.run();
            }, "r" + (i + 1));
            threads[i].start();
        }
        assertTrue(LiveEnvironment.await(() -> robots[0] != null && robots[1] != null
                && robots[0].latest() != null && robots[1].latest() != null, 20_000), "both robots are running");
        for (int i = 0; i < 8; i++) {
            robots[0].keydrive(KeyDrive.Key.FORWARD);
        }
        assertTrue(LiveEnvironment.await(() -> robots[0].latest().vel() > 150, 10_000), "8 presses: 200 mm/s");
        assertTrue(LiveEnvironment.await(() -> env.robot("r1").x() > 1700, 10_000), "moved in the world");
        robots[0].stop();
        assertTrue(LiveEnvironment.await(() -> robots[0].latest().vel() == 0, 10_000), "stops");
        assertTrue(robots[1].latest().vel() == 0, "r2 was not driven");
    }
}
