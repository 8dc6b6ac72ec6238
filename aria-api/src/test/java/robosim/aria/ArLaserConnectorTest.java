package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * ARIA's lasers as ArLaser.h, ArLMS2xx.cpp and ArLaserConnector.cpp have them: the LMS200's choices,
 * the laser arguments, the robot's laser map, and a scan read through the settings.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class ArLaserConnectorTest {
    private final ByteArrayOutputStream log = new ByteArrayOutputStream();

    @BeforeEach
    void captureTheLog() {
        Aria.init();
        ArLog.setStream(new PrintStream(log, true, StandardCharsets.UTF_8));
    }

    @AfterEach
    void release() {
        ArLog.setStream(null);
        Aria.uninit();
    }

    private String log() {
        return log.toString(StandardCharsets.UTF_8);
    }

    private static ArArgumentParser args(String line) {
        return new ArArgumentParser(line.isEmpty() ? new String[0] : line.split(" "));
    }

    @Test
    void anLms2xxOffersAriasChoicesWithAriasDefaults() {
        ArLMS2xx laser = new ArLMS2xx(1);
        assertEquals("lms2xx_1", laser.getName());
        assertEquals(List.of("180", "100"), laser.getDegreesChoices());
        assertEquals("180", laser.getDegreesChoice());
        assertEquals(-90, laser.getStartDegrees());
        assertEquals(90, laser.getEndDegrees());
        assertEquals("one|half", laser.getIncrementChoicesString());
        assertEquals(1.0, laser.getIncrement());
        assertEquals("1mm", laser.getUnitsChoice());
        assertEquals("1ref", laser.getReflectorBitsChoice());
        assertEquals(32000, laser.getAbsoluteMaxRange(), "8 m times 4 with one reflector bit, in mm");
        assertEquals(8102, laser.getDefaultTcpPort());
        assertFalse(laser.canSetDegrees());
        assertFalse(laser.setStartDegrees(-45), "an LMS2xx chooses its degrees");
        assertFalse(laser.canSetPowerControlled());
        assertFalse(laser.chooseDegrees("90"));
        assertTrue(log().contains("lms2xx_1: Bad degrees choice 90, choices are 180|100"), log());
        assertTrue(laser.chooseDegrees("100"));
        assertEquals(-50, laser.getStartDegrees());
        assertEquals(50, laser.getEndDegrees());
        assertFalse(laser.setIncrement(0.25));
        assertEquals(1.0, laser.getIncrement(), "a refused setting leaves it");
    }

    @Test
    void theArgumentsSetUpLaserOneFromTheParameterFileAndConnectItWhenAsked() {
        ArRobot robot = Cycles.p3dxRobot();
        ArLaserConnector connector = new ArLaserConnector(
                args("-connectLaser -ld 100 -li half -lu 1cm -lrb 2ref -lf true -lair 10:12,-5 -lmr 5000 -lp COM3"),
                robot, null);
        assertTrue(connector.parseArgs());
        ArLaser laser = connector.getLaser(1);
        assertEquals("lms2xx_1", laser.getName());
        assertTrue(connector.setupLaser(laser, 1));
        assertEquals("100", laser.getDegreesChoice());
        assertEquals(0.5, laser.getIncrement());
        assertEquals("1cm", laser.getUnitsChoice());
        assertEquals("2ref", laser.getReflectorBitsChoice());
        assertTrue(laser.getFlipped());
        assertEquals(Set.of(-5, 10, 11, 12), laser.getIgnoreReadings());
        assertEquals(5000, laser.getMaxRange());
        // the robot is not connected, so the laser cannot be: it fails, saying why, and is not kept
        assertFalse(connector.connectLasers());
        assertTrue(log().contains("is not connected: connect the robot first"), log());
        assertNull(robot.findLaser(1));
    }

    @Test
    void logLaserDataLogsEachLasersSettingsAsAriaDoes() {
        ArLaserConnector connector = new ArLaserConnector(args("-connectLaser -lp COM3 -lpt serial -rltp 8102 -lf true"),
                Cycles.p3dxRobot(), null);
        connector.logLaserData();
        assertEquals("ArLaserConnector: command-line arguments have not yet been parsed\n", log());
        assertTrue(connector.parseArgs());
        log.reset();
        connector.logLaserData();
        assertEquals("ArLaserConnector: laser #1: lms2xx_1: will connect to this laser, port=COM3, portType=serial,"
                + " remoteTCPPort=8102, flipped=1, fov=(inf, -inf), increment=-inf.\n"
                + "ArLaserConnector: command-line arguments have been parsed.\n", log());
    }

    @Test
    void otherTypesSecondLasersAndBadValuesAreRefusedWithTheReason() {
        assertFalse(new ArLaserConnector(args("-lt urg"), Cycles.p3dxRobot(), null).parseArgs());
        assertTrue(log().contains("Unknown laser type urg for laser 1, choices are lms2xx"), log());
        assertFalse(new ArLaserConnector(args("-laserType2 lms2xx"), Cycles.p3dxRobot(), null).parseArgs());
        assertTrue(log().contains("laser 2: RoboSim simulates one laser per robot"), log());
        assertFalse(new ArLaserConnector(args("-lf maybe"), Cycles.p3dxRobot(), null).parseArgs());
        ArLaserConnector units = new ArLaserConnector(args("-lu 1m"), Cycles.p3dxRobot(), null);
        assertTrue(units.parseArgs());
        assertFalse(units.setupLaser(units.getLaser(1), 1));
        assertTrue(log().contains("lms2xx_1: Bad units choice 1m, choices are 1mm|1cm|10cm"), log());
    }

    @Test
    void theRobotKeepsItsLasersByNumber() {
        ArRobot robot = Cycles.p3dxRobot();
        ArLMS2xx first = new ArLMS2xx(1);
        assertTrue(robot.addLaser(first, 1));
        assertTrue(robot.addLaser(first, 1), "the same laser again is no change");
        assertFalse(robot.addLaser(new ArLMS2xx(2), 1));
        assertTrue(log().contains("there is already a laser of that number (called lms2xx_1)"), log());
        assertSame(first, robot.findLaser(1));
        assertSame(first, robot.findRangeDevice("lms2xx_1"), "a range device too");
        assertEquals(1, robot.getNumLasers());
        assertTrue(robot.remLaser(1));
        assertFalse(robot.hasLaser(first));
        assertNull(robot.findRangeDevice("lms2xx_1"));
    }

    @Test
    void aScanIsReadThroughTheFieldOfViewTheUnitsTheMirrorAndTheIgnoredAngles() {
        ArRobot robot = Cycles.p3dxRobot();
        ArLMS2xx laser = new ArLMS2xx(1);
        robot.addLaser(laser, 1);
        laser.chooseDegrees("100");
        laser.chooseUnits("10cm");
        laser.setFlipped(true);
        laser.addIgnoreReading(0);
        int[] scan = new int[181];
        Arrays.fill(scan, 1234);
        Cycles.cycle(robot, 100, 0, 0, 0, new int[0], scan);
        List<ArSensorReading> raw = laser.getRawReadings();
        assertEquals(101, raw.size(), "the beams from -50° to 50°");
        assertEquals(1200, raw.get(0).getRange(), "rounded to 10 cm");
        // mirrored: the first beam, the laser's rightmost, reads as its leftmost
        assertEquals(50, raw.get(0).getSensorTh(), 1e-9);
        assertEquals(100, laser.getCurrentBuffer().size(), "every beam hit but the ignored one at 0°");
        assertEquals(101, laser.getReadingCount());
    }
}
