package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** ARIA's ArSensorReading: a sensor's mounting, and where a new reading's echo lies. */
class ArSensorReadingTest {
    @Test
    void aSensorThatHasNotReportedReadsItsInitialRangeAndIsIgnored() {
        ArSensorReading r = new ArSensorReading(100, 50, 370, 5000);
        assertEquals(5000, r.getRange());
        assertTrue(r.getIgnoreThisReading());
        assertEquals(100, r.getSensorX());
        assertEquals(50, r.getSensorY());
        assertEquals(10, r.getSensorTh(), 1e-9, "normalised");
        ArPose mount = r.getSensorPosition();
        assertEquals(100, mount.getX());
        assertEquals(50, mount.getY());
        assertEquals(10, mount.getTh(), 1e-9);
    }

    @Test
    void newDataPlacesTheEchoInTheRobotsFrameAndInTheWorld() {
        ArSensorReading r = new ArSensorReading(100, 50, 90, 5000); // looking left
        r.newData(400, new ArPose(1000, 2000, 90), 7, 700); // the robot faces +y
        assertEquals(400, r.getRange());
        assertFalse(r.getIgnoreThisReading());
        assertEquals(100, r.getLocalX(), 1e-9);
        assertEquals(450, r.getLocalY(), 1e-9);
        assertEquals(1000 - 450, r.getX(), 1e-9, "the robot's left is -x");
        assertEquals(2000 + 100, r.getY(), 1e-9);
        assertEquals(7, r.getCounterTaken());
        assertEquals(700, r.getTimeTaken());
        assertTrue(r.isNew(7));
        assertFalse(r.isNew(8));
        assertEquals(1000, r.getPoseTaken().getX());
    }

    @Test
    void aSensorMovedOnTheRobotTakesItsNextReadingFromThere() {
        ArSensorReading r = new ArSensorReading(0, 0, 0, 5000);
        r.resetSensorPosition(200, -100, -90);
        assertEquals(200, r.getSensorX());
        assertEquals(-100, r.getSensorY());
        assertEquals(-90, r.getSensorTh(), 1e-9);
        r.newData(300, new ArPose(), 1, 100);
        assertEquals(200, r.getX(), 1e-9);
        assertEquals(-400, r.getY(), 1e-9);
    }
}
