package robosim.env.sensors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;
import robosim.protocol.RobotState;
import robosim.protocol.SonarReading;

/**
 * The sonar ring fired in sequence: one transducer of each bank of eight every msPerFiring ms, in
 * index order; the state marks which readings are new. Worlds step 100 ms.
 */
class SonarSequenceTest {
    @Test
    void aPeriodicSensorCountsTheFiringsInAStep() {
        PeriodicSensor clock = new PeriodicSensor(40);
        // firings at 40 and 80 fall in (0, 100]; 120, 160, 200 in (100, 200]
        assertEquals(2, clock.firings(0, 100));
        assertEquals(1, clock.firstFiring(0, 100));
        assertEquals(3, clock.firings(100, 200));
        assertEquals(3, clock.firstFiring(100, 200));
        assertEquals(0, clock.firings(100, 100));
        assertThrows(IllegalArgumentException.class, () -> new PeriodicSensor(0));
    }

    @Test
    void sixteenSonarsFireInPairsOfTheTwoBanks() {
        SonarSequence seq = new SonarSequence(40, 16);
        assertEquals(0xFFFF, seq.fire(0), "the first reading fires the whole ring");
        // firings 1 and 2 (40, 80 ms): places 1 and 2, so transducers 1, 2, 9, 10
        assertEquals(1L << 1 | 1L << 2 | 1L << 9 | 1L << 10, seq.fire(100));
        // firings 3, 4, 5 (120, 160, 200 ms): transducers 3, 4, 5, 11, 12, 13
        assertEquals(0b0011_1000_0011_1000L, seq.fire(200));
        // firings 6, 7 (240, 280 ms): transducers 6, 7, 14, 15
        assertEquals(1L << 6 | 1L << 7 | 1L << 14 | 1L << 15, seq.fire(300));
        // firings 8, 9, 10 (320, 360, 400 ms): places 0, 1, 2 again
        assertEquals(0b0000_0111_0000_0111L, seq.fire(400));
    }

    @Test
    void aRingSmallerThanABankFiresOneTransducerAtATime() {
        SonarSequence seq = new SonarSequence(100, 5);
        seq.fire(0);
        assertEquals(1L << 1, seq.fire(100));
        assertEquals(1L << 2 | 1L << 3, seq.fire(300));
        // a long gap fires the whole ring
        assertEquals(0b11111, seq.fire(10_000));
    }
}
