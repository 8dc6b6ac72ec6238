package robosim.scout;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;

/**
 * conf_sn's firing order and period, emulated from per-step readings: which sonars change in which
 * step. In step k every sonar i reads 16·k + i inches, so a value says the step it was taken in.
 */
class SonarFiringTest {
    private static final long NEVER = 255;
    private final ScriptedScout scout = new ScriptedScout();

    /** Readings of step k, in mm: sonar i reads 16·k + i inches. */
    private static int[] readings(long k) {
        int[] mm = new int[16];
        for (int i = 0; i < 16; i++) {
            mm[i] = (int) Math.round((16 * k + i) * 25.4);
        }
        return mm;
    }

    private void queueSteps(int from, int to) {
        for (int k = from; k <= to; k++) {
            scout.queue(ScriptedScout.sonarAt(k, readings(k)));
        }
    }

    /** The sonar part of State after the next step. */
    private long[] nextSonar() {
        assertTrue(scout.get_sn());
        long[] s = new long[16];
        System.arraycopy(scout.State, StateVector.STATE_SONAR_0, s, 0, 16);
        return s;
    }

    /** What State's sonars must hold: sonar → step of its latest firing (0: never). */
    private static long[] expect(int... stepBySonar) {
        long[] s = new long[16];
        for (int i = 0; i < 16; i++) {
            s[i] = stepBySonar[i] == 0 ? NEVER : 16L * stepBySonar[i] + i;
        }
        return s;
    }

    @Test
    void byDefaultEverySonarFiresEveryStep() {
        queueSteps(1, 2);
        assertArrayEquals(expect(1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1), nextSonar());
        assertArrayEquals(expect(2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2), nextSonar());
    }

    @Test
    void rate10FiresEvery40MsThroughTheOrderAcrossSteps() {
        // firings at 40 (s0), 80 (s4) | 120 (s8), 160 (s12), 200 (s0) | 240 (s4), 280 (s8) | 320 (s12), 360 (s0), 400 (s4)
        assertTrue(scout.conf_sn(10, new int[] {0, 4, 8, 12, 255}));
        queueSteps(1, 4);
        assertArrayEquals(expect(1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0), nextSonar());
        assertArrayEquals(expect(2, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0), nextSonar());
        assertArrayEquals(expect(2, 0, 0, 0, 3, 0, 0, 0, 3, 0, 0, 0, 2, 0, 0, 0), nextSonar());
        assertArrayEquals(expect(4, 0, 0, 0, 4, 0, 0, 0, 3, 0, 0, 0, 4, 0, 0, 0), nextSonar());
    }

    @Test
    void rate25FiresOneSonarAStepInOrder() {
        assertTrue(scout.conf_sn(25, new int[] {15, 1, 7}));
        queueSteps(1, 4);
        assertArrayEquals(expect(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1), nextSonar());
        assertArrayEquals(expect(0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1), nextSonar());
        assertArrayEquals(expect(0, 2, 0, 0, 0, 0, 0, 3, 0, 0, 0, 0, 0, 0, 0, 1), nextSonar());
        assertArrayEquals(expect(0, 2, 0, 0, 0, 0, 0, 3, 0, 0, 0, 0, 0, 0, 0, 4), nextSonar());
    }

    @Test
    void rate50FiresEveryOtherStepAndTheOrderEndsAt255() {
        assertTrue(scout.conf_sn(50, new int[] {3, 255, 7}));
        queueSteps(1, 4);
        assertArrayEquals(expect(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0), nextSonar());
        assertArrayEquals(expect(0, 0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0), nextSonar());
        assertArrayEquals(expect(0, 0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0), nextSonar());
        assertArrayEquals(expect(0, 0, 0, 4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0), nextSonar());
    }

    @Test
    void aScheduleStartsFromTheStateItWasMadeIn() {
        queueSteps(1, 3);
        nextSonar();
        nextSonar(); // now at step 2, time 200: every sonar read in step 2
        assertTrue(scout.conf_sn(75, new int[] {5, 6})); // firings at 500 (s5), 800 (s6)
        assertArrayEquals(expect(2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2), nextSonar());
        queueSteps(4, 8);
        nextSonar();
        assertArrayEquals(expect(2, 2, 2, 2, 2, 5, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2), nextSonar());
        nextSonar();
        nextSonar();
        assertArrayEquals(expect(2, 2, 2, 2, 2, 5, 8, 2, 2, 2, 2, 2, 2, 2, 2, 2), nextSonar());
    }

    @Test
    void aSonarFiringWhileTheSonarsAreOffKeepsItsValue() {
        assertTrue(scout.conf_sn(25, new int[] {0, 1}));
        scout.queue(ScriptedScout.sonarAt(1, readings(1)), ScriptedScout.sonarAt(2, new int[0]),
                ScriptedScout.sonarAt(3, readings(3)));
        nextSonar();
        assertArrayEquals(expect(1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0), nextSonar());
        assertArrayEquals(expect(3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0), nextSonar());
    }

    @Test
    void aRepeatedSonarFiresEachTimeItComesRound() {
        assertTrue(scout.conf_sn(25, new int[] {2, 2, 9}));
        queueSteps(1, 3);
        assertArrayEquals(expect(0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0), nextSonar());
        assertArrayEquals(expect(0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0), nextSonar());
        assertArrayEquals(expect(0, 0, 2, 0, 0, 0, 0, 0, 0, 3, 0, 0, 0, 0, 0, 0), nextSonar());
    }

    @Test
    void aLongGapStillEndsWithEachSonarsLatestFiring() {
        assertTrue(scout.conf_sn(1, new int[] {0, 1, 2}));
        scout.deliver(ScriptedScout.sonarAt(50, readings(14)));
        assertTrue(scout.get_sn());
        assertEquals(16 * 14, scout.State[StateVector.STATE_SONAR_0], "a time jump fires each sonar once more");
        assertEquals(NEVER, scout.State[StateVector.STATE_SONAR_3]);
    }

    @Test
    void badConfigurationsAreRefusedAndSendNothing() {
        assertFalse(scout.conf_sn(0, new int[] {0}));
        assertFalse(scout.conf_sn(10, new int[] {0, 16}));
        assertFalse(scout.conf_sn(10, new int[] {-1}));
        assertFalse(scout.conf_sn(10, null));
        assertEquals(List.of(), scout.sent);
    }

    @Test
    void anEmptyOrderSwitchesTheSonarsOffAndAnyOtherOn() {
        assertTrue(scout.conf_sn(10, new int[] {255, 3}));
        assertTrue(scout.conf_sn(10, new int[] {3}));
        assertEquals(List.of(new Command.SetSonar(false), new Command.SetSonar(true)), scout.sent);
    }

    @Test
    void entriesAfterTheSixteenthAreIgnored() {
        int[] order = new int[20];
        order[16] = 99;
        assertTrue(scout.conf_sn(10, order), "the first 16 entries, all sonar 0, are the order");
    }
}
