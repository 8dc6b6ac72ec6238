package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import robosim.protocol.RobotParameters;

/** ArSick: a SICK LMS200's scan turned into raw readings and range-device readings. */
class ArSickTest {
    private static final int[] NO_SONAR = new int[0];

    private static int[] scan(int readings, int range) {
        int[] s = new int[readings];
        Arrays.fill(s, range);
        return s;
    }

    private static ArSick attached(ArRobot robot) {
        ArSick sick = new ArSick();
        robot.addRangeDevice(sick);
        return sick;
    }

    @Test
    void theDefaultsAreAnLms200s() {
        ArSick sick = new ArSick();
        assertEquals("laser", sick.getName());
        assertEquals(8000, sick.getMaxRange());
        assertEquals(1.0, sick.getIncrement());
        assertFalse(sick.isConnected());
        assertTrue(sick.getRawReadings().isEmpty());
    }

    @Test
    void theP3dxLaserSits18MmAheadOfTheCentre() {
        RobotParameters p = Cycles.p3dx();
        assertEquals(List.of(18.0, 0.0, 0.0), List.of(p.laserX(), p.laserY(), p.laserTh()));
    }

    @Test
    void aOneDegreeScanGives181ReadingsAtTheirGlobalPositions() {
        ArRobot robot = Cycles.p3dxRobot();
        ArSick sick = attached(robot);
        int[] s = scan(181, 500);
        Cycles.cycle(robot, 100, 1000, 2000, 90, NO_SONAR, s);
        List<ArSensorReading> raw = sick.getRawReadings();
        assertEquals(181, raw.size());
        // the robot at (1000, 2000) faces +y; the laser 18 mm ahead of its centre, facing forward
        assertReading(raw.get(0), -90, 1500, 2018);
        assertReading(raw.get(90), 0, 1000, 2518);
        assertReading(raw.get(180), 90, 500, 2018);
        assertReading(raw.get(45), -45, 1000 + 353.5533905932738, 2018 + 353.5533905932738);
    }

    @Test
    void aHalfDegreeScanGives361Readings() {
        ArRobot robot = Cycles.p3dxRobot();
        ArSick sick = attached(robot);
        int[] s = scan(361, 1000);
        s[360] = 2000;
        Cycles.cycle(robot, 100, 0, 0, 0, NO_SONAR, s);
        List<ArSensorReading> raw = sick.getRawReadings();
        assertEquals(361, raw.size());
        assertReading(raw.get(1), -89.5, 18 + 1000 * Math.cos(Math.toRadians(-89.5)),
                1000 * Math.sin(Math.toRadians(-89.5)));
        assertReading(raw.get(90), -45, 18 + 707.10678118654755, -707.10678118654755);
        assertReading(raw.get(180), 0, 1018, 0);
        assertReading(raw.get(360), 90, 18, 2000);
    }

    @Test
    void aTurnedMountTurnsEveryBeam() {
        // mounted 100 mm ahead, 50 mm left, turned 10° left; the robot at (1000, 2000) faces +y
        ArRobot robot = Cycles.robot(Cycles.p3dxWithLaser(100, 50, 10, 8000));
        ArSick sick = attached(robot);
        Cycles.cycle(robot, 100, 1000, 2000, 90, NO_SONAR, scan(181, 500));
        List<ArSensorReading> raw = sick.getRawReadings();
        assertReading(raw.get(80), 0, 950, 2600);
        assertReading(raw.get(170), 90, 450, 2100);
    }

    private static void assertReading(ArSensorReading r, double sensorTh, double x, double y) {
        assertEquals(sensorTh, r.getSensorTh(), 1e-9, "sensor heading");
        assertEquals(x, r.getX(), 1e-6, "global x");
        assertEquals(y, r.getY(), 1e-6, "global y");
    }

    @Test
    void rawReadingsCarryTheCycle() {
        ArRobot robot = Cycles.p3dxRobot();
        ArSick sick = attached(robot);
        Cycles.cycle(robot, 100, 0, 0, 0);
        Cycles.cycle(robot, 200, 300, 400, 45, NO_SONAR, scan(181, 700));
        ArSensorReading r = sick.getRawReadings().get(7);
        assertEquals(700, r.getRange());
        assertEquals(2, r.getCounterTaken());
        assertEquals(200, r.getTimeTaken());
        assertEquals(45, r.getPoseTaken().getTh(), 1e-9);
        assertTrue(r.isNew(robot.getCounter()));
    }

    @Test
    void theRawScanIsTheLatestScan() {
        ArRobot robot = Cycles.p3dxRobot();
        ArSick sick = attached(robot);
        int[] s = scan(181, 700);
        s[3] = 123;
        Cycles.cycle(robot, 100, 0, 0, 0, NO_SONAR, s);
        assertArrayEquals(s, sick.getRawScan());
        Cycles.cycle(robot, 200, 0, 0, 0);
        assertEquals(0, sick.getRawScan().length, "the laser is off");
        assertTrue(sick.getRawReadings().isEmpty());
    }

    @Test
    void onlyReadingsBelowTheMaximumRangeEnterTheBuffers() {
        ArRobot robot = Cycles.p3dxRobot();
        ArSick sick = attached(robot);
        int[] s = scan(181, 8000);
        s[90] = 1500;
        s[100] = 7999;
        Cycles.cycle(robot, 100, 0, 0, 0, NO_SONAR, s);
        assertEquals(2, sick.getCurrentBuffer().size());
        assertEquals(1518, sick.currentReadingPolar(-5, 5), 1e-9);
        assertEquals(1, sick.getCumulativeBuffer().size(), "7999 mm is beyond the cumulative 3000 mm");
    }

    @Test
    void aWholeScanFillsTheCurrentBuffer() {
        ArRobot robot = Cycles.p3dxRobot();
        ArSick sick = attached(robot);
        Cycles.cycle(robot, 100, 0, 0, 0, NO_SONAR, scan(361, 2000));
        assertEquals(361, sick.getCurrentBuffer().size());
    }

    @ParameterizedTest
    @ValueSource(doubles = {0.25, 2, 0, -1})
    void otherIncrementsAreRejectedNamingTheValueAndTheRule(double increment) {
        ArSick sick = new ArSick();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> sick.setIncrement(increment));
        assertEquals(increment + " was supplied for increment: a SICK LMS200 scans at 1 or 0.5 degrees",
                e.getMessage());
    }

    @Test
    void halfADegreeIsAccepted() {
        ArSick sick = new ArSick();
        sick.setIncrement(0.5);
        assertEquals(0.5, sick.getIncrement());
    }

    @Test
    void blockingConnectWithoutARobotFailsAndSaysWhy() {
        ArSick sick = new ArSick();
        assertFalse(sick.blockingConnect());
        assertTrue(sick.getConnectionError().contains("no robot"), sick.getConnectionError());
        assertFalse(sick.isConnected());
    }

    @Test
    void blockingConnectWithAnUnconnectedRobotFailsAndNamesIt() {
        ArSick sick = attached(Cycles.p3dxRobot());
        assertNull(sick.getConnectionError());
        assertFalse(sick.blockingConnect());
        assertEquals("robot r is not connected: connect the robot first", sick.getConnectionError());
        assertFalse(sick.isConnected());
        sick.disconnect();
        assertFalse(sick.isConnected());
    }

    @Test
    void theMaximumRangeComesFromTheParameterFileUnlessSet() {
        ArSick fromFile = attached(Cycles.robot(Cycles.p3dxWithLaser(0, 0, 0, 4000)));
        assertEquals(4000, fromFile.getMaxRange());
        ArSick chosen = new ArSick();
        chosen.setMaxRange(6000);
        Cycles.robot(Cycles.p3dxWithLaser(0, 0, 0, 4000)).addRangeDevice(chosen);
        assertEquals(6000, chosen.getMaxRange());
    }
}
