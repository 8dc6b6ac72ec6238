package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * ArTime in simulated time, with ARIA's argument order (ariaUtil.h): a.mSecSince(b) is b − a. The
 * test thread belongs to no robot, so "now" is the time of the latest state a robot received.
 */
class ArTimeTest {
    private ArRobot robot;

    @BeforeEach
    void aRobotAt1500Ms() {
        robot = Cycles.p3dxRobot();
        Cycles.cycle(robot, 1500, 0, 0, 0);
    }

    @Test
    void nowIsTheLatestStatesTime() {
        ArTime t = new ArTime();
        assertEquals(1, t.getSec());
        assertEquals(500, t.getMSec());
        assertEquals(1500, t.getTimeMs());
    }

    @Test
    void timeSinceFollowsTheSimulation() {
        ArTime start = new ArTime();
        Cycles.cycle(robot, 3700, 0, 0, 0);
        assertEquals(2200, start.mSecSince());
        assertEquals(2, start.secSince());
        assertEquals(2.2, start.secSinceDouble(), 1e-12);
        assertEquals(-2200, start.mSecTo());
        assertEquals(2200, start.mSecSinceLL());
    }

    @Test
    void theArgumentOrderIsArias() {
        ArTime early = new ArTime();
        ArTime late = new ArTime(early);
        late.addMSec(300);
        assertEquals(300, early.mSecSince(late));
        assertEquals(-300, late.mSecSince(early));
        // ARIA: a.isBefore(b) when b is earlier than a
        assertTrue(late.isBefore(early));
        assertFalse(early.isBefore(late));
        assertTrue(early.isAfter(late));
        assertTrue(early.isAt(new ArTime(early)));
    }

    @Test
    void aTimeInTheFutureCountsDown() {
        ArTime deadline = new ArTime();
        deadline.addMSec(1000);
        Cycles.cycle(robot, 1800, 0, 0, 0);
        assertEquals(700, deadline.mSecTo());
        assertEquals(0, deadline.secTo());
    }

    @Test
    void goingBelowZeroIsRefusedAndZeroes() {
        ArTime t = new ArTime();
        assertFalse(t.addMSec(-1501));
        assertEquals(0, t.getTimeMs());
        assertTrue(new ArTime().addMSec(-1500));
    }

    @Test
    void setToNowTakesTheNewTime() {
        ArTime t = new ArTime();
        Cycles.cycle(robot, 2000, 0, 0, 0);
        t.setToNow();
        assertEquals(2000, t.getTimeMs());
    }

    @Test
    void secondsAndMillisecondsAreSetApart() {
        ArTime t = new ArTime();
        t.setSec(7);
        assertEquals(7500, t.getTimeMs());
        t.setMSec(20);
        assertEquals(7020, t.getTimeMs());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> t.setSec(-1));
        assertEquals("-1 was supplied for sec: simulated time is 0 or more", e.getMessage());
    }

    @Test
    void theSixtyFourBitNamesAnswerAsThePlainOnes() {
        ArTime start = new ArTime(); // 1500
        ArTime later = new ArTime(start);
        assertTrue(later.addMSecLL(2700)); // 4200
        assertEquals(2, start.secSinceLL(later), "4200 - 1500 ms, whole seconds");
        assertEquals(4, later.getSecLL());
        assertEquals(200, later.getMSecLL());
        Cycles.cycle(robot, 3700, 0, 0, 0);
        assertEquals(2, start.secSinceLL(), "2200 ms ago");
        assertEquals(500, later.mSecToLL(), "500 ms ahead");
        assertEquals(0, later.secToLL(), "truncated");
        assertEquals(-2, start.secToLL());
        assertFalse(later.addMSecLL(-5000), "below 0");
        assertEquals(0, later.getTimeMs());
    }
}
