package robosim.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** How the benchmark spreads its robots over client JVMs, and the robots' one decision. */
class BenchRobotsTest {
    @ParameterizedTest
    @CsvSource({"1, 1", "10, 1", "10, 3", "10, 4", "7, 7", "3, 8", "2000, 3", "5000, 64"})
    void everyRobotIsInExactlyOneShareInOrderAndSharesDifferByAtMostOne(int robots, int clients) {
        List<BenchRobots.Share> shares = BenchRobots.split(robots, clients);
        assertEquals(Math.min(robots, clients), shares.size());
        int next = 0;
        int least = Integer.MAX_VALUE;
        int most = 0;
        for (BenchRobots.Share s : shares) {
            assertEquals(next, s.first(), "shares follow each other: " + shares);
            next += s.count();
            least = Math.min(least, s.count());
            most = Math.max(most, s.count());
        }
        assertEquals(robots, next, "every robot is in a share: " + shares);
        assertTrue(most - least <= 1, "as even as possible: " + shares);
    }

    @Test
    void tenRobotsOverThreeClientsGiveTheFirstClientTheRobotLeftOver() {
        assertEquals(List.of(new BenchRobots.Share(0, 4), new BenchRobots.Share(4, 3), new BenchRobots.Share(7, 3)),
                BenchRobots.split(10, 3));
    }

    @Test
    void noRobotsOrNoClientsAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> BenchRobots.split(0, 1));
        assertThrows(IllegalArgumentException.class, () -> BenchRobots.split(1, 0));
    }

    @Test
    void theLaserBlocksOnlyWhatIsAheadAndNear() {
        int[] far = new int[181];
        java.util.Arrays.fill(far, 8000);
        int[] nearAhead = far.clone();
        nearAhead[95] = 500; // 5 degrees left of ahead
        int[] nearAside = far.clone();
        nearAside[0] = 300; // 90 degrees right
        assertFalse(BenchRobots.blocked(i -> 5000, 16, far));
        assertTrue(BenchRobots.blocked(i -> 5000, 16, nearAhead));
        assertFalse(BenchRobots.blocked(i -> 5000, 16, nearAside));
        assertFalse(BenchRobots.blocked(i -> 5000, 16, new int[0]));
        assertTrue(BenchRobots.blocked(i -> i == 3 ? 400 : 5000, 16, new int[0]), "a front sonar blocks");
        assertFalse(BenchRobots.blocked(i -> i == 12 ? 400 : 5000, 16, new int[0]), "a rear sonar does not");
    }

    @Test
    void sensorsAreNamedAsOnTheCommandLine() {
        assertEquals(BenchSensors.SONAR, BenchSensors.named("sonar").orElseThrow());
        assertEquals(BenchSensors.LASER, BenchSensors.named(" Laser ").orElseThrow());
        assertTrue(BenchSensors.named("radar").isEmpty());
        assertEquals("sonar+laser", BenchSensors.LASER.label());
    }
}
