package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** ArSensorReading's ARIA calls (ArSensorReading.h/.cpp) and the original RoboSim's newData. */
class ArSensorReadingAriaTest {
    private static ArTime at(long ms) {
        return ArTime.ofMs(ms);
    }

    @Test
    void ariasConstructorStartsWithAriasValues() {
        ArSensorReading r = new ArSensorReading(100, 0, 45);
        assertEquals(5000, r.getRange());
        assertEquals(-1, r.getX());
        assertEquals(-1, r.getY());
        assertEquals(-1, r.getXTaken());
        assertEquals(-1, r.getThTaken());
        assertFalse(r.getIgnoreThisReading());
        assertEquals(0, r.getCounterTaken());
        assertEquals(0, r.getExtraInt());
        assertEquals(Math.sqrt(0.5), r.getSensorDX(), 1e-12);
        assertEquals(Math.sqrt(0.5), r.getSensorDY(), 1e-12);
        assertEquals(0, new ArSensorReading().getSensorTh());
    }

    @Test
    void ariasNewDataTransformsTheLocalEchoWithTheTransformGiven() {
        ArSensorReading r = new ArSensorReading(100, 50, 90); // looking left
        ArPose robot = new ArPose(1000, 2000, 90);
        ArPose encoder = new ArPose(10, 20, 0);
        r.setAdjusted(true);
        r.newData(400, robot, encoder, new ArTransform(new ArPose(), robot), 7, at(700), true, 200);
        assertEquals(400, r.getRange());
        assertEquals(100, r.getLocalPose().getX(), 1e-9);
        assertEquals(450, r.getLocalPose().getY(), 1e-9);
        assertEquals(1000 - 450, r.getX(), 1e-9);
        assertEquals(2000 + 100, r.getY(), 1e-9);
        assertEquals(1000, r.getXTaken());
        assertEquals(2000, r.getYTaken());
        assertEquals(90, r.getThTaken());
        assertEquals(10, r.getEncoderPoseTaken().getX());
        assertEquals(7, r.getCounterTaken());
        assertEquals(700, r.getTimeTaken());
        assertTrue(r.getIgnoreThisReading());
        assertEquals(200, r.getExtraInt());
        assertFalse(r.getAdjusted(), "new data is not adjusted");
    }

    @Test
    void ariasShortNewDataIsNotIgnoredAndHasNoExtra() {
        ArSensorReading r = new ArSensorReading(0, 0, 0);
        r.setIgnoreThisReading(true);
        r.setExtraInt(9);
        r.newData(300, new ArPose(), new ArPose(), new ArTransform(), 1, at(100));
        assertFalse(r.getIgnoreThisReading());
        assertEquals(0, r.getExtraInt());
        assertEquals(300, r.getX(), 1e-9);
        assertThrows(IllegalArgumentException.class,
                () -> r.newData(-1, new ArPose(), new ArPose(), new ArTransform(), 1, at(100)));
    }

    @Test
    void newDataFromAPositionTruncatesTheRange() {
        ArSensorReading r = new ArSensorReading(100, 0, 30);
        ArPose robot = new ArPose(0, 0, 180);
        r.newData(3, 4, robot, robot, new ArTransform(new ArPose(), robot), 2, at(200));
        assertEquals(5, r.getRange());
        assertEquals(103, r.getLocalX(), 1e-9, "relative to the sensor's point, in the robot's axes");
        assertEquals(4, r.getLocalY(), 1e-9);
        assertEquals(-103, r.getX(), 1e-9);
        assertEquals(-4, r.getY(), 1e-9);
        r.newData(1, 1, robot, robot, new ArTransform(), 3, at(300));
        assertEquals(1, r.getRange(), "sqrt(2) truncated");
    }

    @Test
    void theOriginalRoboSimsNewDataTakesTheGlobalPosition() {
        ArSensorReading r = new ArSensorReading(100, 0, 90, 5000);
        r.newData(500, new ArPose(10, 20, 0), 3, 300);
        r.newData(250, 1234.5, -678.9, 4);
        assertEquals(250, r.getRange());
        assertEquals(1234.5, r.getX());
        assertEquals(-678.9, r.getY());
        assertEquals(100, r.getLocalX(), 1e-9);
        assertEquals(250, r.getLocalY(), 1e-9);
        assertEquals(4, r.getCounterTaken());
        assertTrue(r.isNew(4));
        assertFalse(r.getIgnoreThisReading());
        assertEquals(10, r.getXTaken(), "the pose taken is not given, so it stays");
        assertEquals(300, r.getTimeTaken());
    }

    @Test
    void roboSimsNewDataTakesThePoseAsTheEncoderPoseToo() {
        ArSensorReading r = new ArSensorReading(0, 0, 0, 5000);
        r.newData(100, new ArPose(5, 6, 7), 1, 100);
        assertEquals(new ArPose(5, 6, 7), r.getEncoderPoseTaken());
    }

    @Test
    void transformsMoveTheirOwnPoses() {
        ArSensorReading r = new ArSensorReading(0, 0, 0, 5000);
        r.newData(100, new ArPose(0, 0, 0), 1, 100);
        ArTransform shift = new ArTransform(new ArPose(), new ArPose(1000, 0, 0));
        r.applyTransform(shift);
        assertEquals(1100, r.getX(), 1e-9);
        assertEquals(1000, r.getXTaken(), 1e-9);
        assertEquals(0, r.getEncoderPoseTaken().getX(), 1e-9, "applyTransform leaves the encoder pose");
        assertEquals(100, r.getLocalX(), 1e-9);
        r.applyEncoderTransform(shift);
        assertEquals(1000, r.getEncoderPoseTaken().getX(), 1e-9);
        assertEquals(1100, r.getX(), 1e-9);
    }

    @Test
    void resetSensorPositionSkipsTheSamePositionUnlessForced() {
        ArSensorReading r = new ArSensorReading(10, 20, 30);
        r.resetSensorPosition(10, 20, 30.000001, false);
        assertEquals(30, r.getSensorTh(), 0, "within 0.00001 degrees: unchanged");
        r.resetSensorPosition(10, 20, 30.000001, true);
        assertEquals(30.000001, r.getSensorTh(), 1e-12);
        r.resetSensorPosition(11, 20, 30, false);
        assertEquals(11, r.getSensorX());
    }
}
