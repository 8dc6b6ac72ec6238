package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArRobot;
import robosim.cli.Background;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;

/**
 * The p3dx's sonar ring fired in sequence on a live Environment: its parameter file gives
 * SonarCycle 40, so each 100 ms cycle two or three places of the two banks of eight fire, in order,
 * and isSonarNew is true for those alone.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class SonarSequenceEndToEndTest {
    @TempDir
    Path dir;

    @Test
    void eachCycleTheNextPlacesOfBothBanksFire() throws Exception {
        Path world = dir.resolve("room.xml");
        Files.writeString(world, """
                <world name="room" width="8000" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="4000" y="3000" th="0" params="%s"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p")));
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world), 7, ServerOptions.loopback())) {
            CompletableFuture<List<Integer>> seen = Background.supply("robot r1", () -> {
                ArRobot robot = new ArRobot("r1", "127.0.0.1", env.robotPort(),
                        LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p").toString());
                List<Integer> masks = new ArrayList<>();
                robot.addUserTask("watch", 0, () -> {
                    int mask = 0;
                    for (int i = 0; i < robot.getNumSonar(); i++) {
                        mask |= robot.isSonarNew(i) ? 1 << i : 0;
                    }
                    masks.add(mask);
                });
                if (!robot.blockingConnect()) {
                    throw new IllegalStateException(robot.getConnectionError());
                }
                robot.sleepSimulated(1500);
                robot.disconnect();
                synchronized (masks) {
                    return List.copyOf(masks);
                }
            });
            List<Integer> masks = seen.get(60, TimeUnit.SECONDS);
            env.await(60);

            int firstPartial = -1;
            for (int i = 0; i < masks.size(); i++) {
                if (masks.get(i) != 0xFFFF) {
                    firstPartial = i;
                    break;
                }
            }
            assertTrue(firstPartial > 0, "the whole ring fires first, then in sequence: " + masks);
            int nextPlace = -1;
            for (int i = firstPartial; i < masks.size(); i++) {
                int mask = masks.get(i);
                int places = mask & 0xFF;
                assertEquals(places | places << 8, mask, "both banks fire the same places: " + masks);
                int count = Integer.bitCount(places);
                assertTrue(count == 2 || count == 3, "100 ms holds 2 or 3 firings of 40 ms: " + masks);
                // the places run on from where the last cycle stopped, wrapping from 7 to 0
                int start = nextPlace < 0 ? startOfRun(places) : nextPlace;
                for (int k = 0; k < count; k++) {
                    assertTrue((places >> ((start + k) % 8) & 1) != 0, "places in order: " + masks);
                }
                nextPlace = (start + count) % 8;
            }
            assertTrue(masks.size() - firstPartial >= 8, "enough cycles watched: " + masks);
        }
    }

    /** @return the first place of a run of places that may wrap from 7 to 0 */
    private static int startOfRun(int places) {
        for (int p = 0; p < 8; p++) {
            if ((places >> p & 1) != 0 && (places >> ((p + 7) % 8) & 1) == 0) {
                return p;
            }
        }
        return 0;
    }
}
