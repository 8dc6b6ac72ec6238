package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.scout.StateVector.STATE_BUMPER;
import static robosim.scout.StateVector.STATE_SONAR_0;

import java.nio.file.Path;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.scout.Scout;

/** The Scout's sonar ring and bumper ring over TCP, several Scouts in one world. */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class ScoutSensorsEndToEndTest {
    @TempDir
    Path dir;

    private static Scout connect(String name, int port) {
        Scout s = new Scout(name, "127.0.0.1", port);
        if (!s.connect_robot()) {
            throw new IllegalStateException(s.getConnectionError());
        }
        return s;
    }

    private static long[] sonarInches(String name, int port) {
        Scout s = connect(name, port);
        s.gs();
        long[] inches = new long[16];
        System.arraycopy(s.State, STATE_SONAR_0, inches, 0, 16);
        s.disconnect_robot();
        return inches;
    }

    @Test
    void sonarsReadWallsInWholeInchesUpTo255() throws Exception {
        // s1's transducers sit 190 mm from its centre: a box face 1000 mm ahead, walls 4420 mm behind,
        // 4710 mm to the left and 2710 mm to the right; s2 sees nothing within 6477 mm ahead
        Path world = ThreadedRun.world(dir, "walls.xml", """
                <world name="walls" width="12000" height="8000" boundary="true">
                  <polygon points="5900,2500 6500,2500 6500,3500 5900,3500" height="500"/>
                  <robot name="s1" type="scout" x="4710" y="3000" th="0" params="%ROBOTS%/scout.p"/>
                  <robot name="s2" type="scout" x="1000" y="6000" th="0" params="%ROBOTS%/scout.xml"/>
                </world>
                """);
        try (ThreadedRun run = new ThreadedRun(world, 1, 0)) {
            Future<long[]> s1 = run.robot(() -> sonarInches("s1", run.port()));
            Future<long[]> s2 = run.robot(() -> sonarInches("s2", run.port()));
            long[] near = s1.get(60, TimeUnit.SECONDS);
            long[] far = s2.get(60, TimeUnit.SECONDS);
            run.await();
            assertEquals(39, near[0], 1, "1000 mm ahead is 39 inches");
            assertEquals(185, near[4], 1, "4710 mm to the left");
            assertEquals(174, near[8], 1, "4420 mm behind");
            assertEquals(107, near[12], 1, "2710 mm to the right");
            assertEquals(255, far[0], "nothing within range reads 255");
        }
    }

    /** Drives until a bumper touches, then backs off: the bumper bits at contact and after. */
    private static long[] bump(String name, int port, int towards) {
        Scout s = connect(name, port);
        s.vm(towards, towards, 0);
        long touched = 0;
        for (int i = 0; i < 200 && touched == 0 && s.get_bp(); i++) {
            touched = s.State[STATE_BUMPER];
        }
        s.st();
        s.pr(-towards, -towards, 0);
        assertTrue(s.ws(1, 1, 0, 10));
        s.get_bp();
        long after = s.State[STATE_BUMPER];
        s.disconnect_robot();
        return new long[] {touched, after};
    }

    @Test
    void bumperBitsSetOnContactInTheSectorThatTouchesAndClearAfterBackingOff() throws Exception {
        // s1 heads 60 degrees into the right-hand wall: it touches at -60 degrees, sector 5;
        // s2 backs into the wall behind it (sector 3); s3 drives head on into a box (sector 0)
        Path world = ThreadedRun.world(dir, "bumps.xml", """
                <world name="bumps" width="6000" height="6000" boundary="true">
                  <polygon points="2000,4200 2600,4200 2600,4800 2000,4800" height="500"/>
                  <robot name="s1" type="scout" x="5000" y="1000" th="60" params="%ROBOTS%/scout.p"/>
                  <robot name="s2" type="scout" x="1000" y="2500" th="0" params="%ROBOTS%/scout.p"/>
                  <robot name="s3" type="scout" x="1000" y="4500" th="0" params="%ROBOTS%/scout.p"/>
                </world>
                """);
        try (ThreadedRun run = new ThreadedRun(world, 1, 0)) {
            Future<long[]> s1 = run.robot(() -> bump("s1", run.port(), 100));
            Future<long[]> s2 = run.robot(() -> bump("s2", run.port(), -100));
            Future<long[]> s3 = run.robot(() -> bump("s3", run.port(), 100));
            long[] frontRight = s1.get(60, TimeUnit.SECONDS);
            long[] rear = s2.get(60, TimeUnit.SECONDS);
            long[] front = s3.get(60, TimeUnit.SECONDS);
            run.await();
            assertEquals(1 << 5, frontRight[0], "sector 5, front right");
            assertEquals(1 << 3, rear[0], "sector 3, behind");
            assertEquals(1, front[0], "sector 0, dead ahead");
            assertEquals(0, frontRight[1], "cleared after backing off");
            assertEquals(0, rear[1]);
            assertEquals(0, front[1]);
        }
    }
}
