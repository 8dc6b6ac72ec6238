package robosim.comms;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.comms.Messages.ids;
import static robosim.comms.Messages.loss;
import static robosim.comms.Messages.toRobot;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Messages lost at random, the randomness drawn from the run's seed. */
class CommunicationsSystemLossTest {
    private static final List<String> ROBOTS = List.of("a", "b");
    private static final Set<String> ALL = Set.copyOf(ROBOTS);
    private static final int MESSAGES = 10_000;

    /** Sends {@code MESSAGES} messages from a to b in one step; @return the ids b received */
    private static Set<Long> delivered(double lossProbability, long seed) {
        CommunicationsSystem comms = new CommunicationsSystem(ROBOTS, loss(lossProbability), seed);
        for (long id = 0; id < MESSAGES; id++) {
            comms.submit(1, "a", toRobot(id, "b"));
        }
        FakePositions positions = new FakePositions().put("a", 0, 0).put("b", 1000, 0);
        List<Long> ids = ids(comms.deliver(1, positions, ALL), "b");
        Set<Long> set = new HashSet<>(ids);
        assertEquals(ids.size(), set.size(), "a message was delivered twice");
        return set;
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 42, -7})
    void lossOfThreeTenthsDeliversSeventyPercent(long seed) {
        int n = delivered(0.3, seed).size();
        assertTrue(n >= 6800 && n <= 7200, () -> n + " of " + MESSAGES + " delivered, expected 7000 ± 200");
    }

    @Test
    void sameSeedLosesTheSameMessages() {
        assertEquals(delivered(0.3, 42), delivered(0.3, 42));
    }

    @Test
    void anotherSeedLosesOtherMessages() {
        assertNotEquals(delivered(0.3, 42), delivered(0.3, 43));
    }

    @Test
    void lossZeroDeliversEveryMessage() {
        assertEquals(MESSAGES, delivered(0, 42).size());
    }

    @Test
    void lossOneDeliversNothing() {
        assertEquals(0, delivered(1, 42).size());
    }
}
