package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.hw.RobotSensorResponse;
import robosim.params.RobotParameterFiles;
import robosim.protocol.BatteryReading;
import robosim.protocol.CapturedLog;
import robosim.protocol.Command;
import robosim.protocol.RobotState;

/**
 * Flags, charge, temperature, identity, sonar boards, trying-to-move and the wheel encoders answer
 * as ARIA's ArRobot answers for what the simulation gives.
 */
class ArRobotStateExtrasTest {
    @Test
    void theFlagsCarryTheMotorsAndTheSonars() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        robot.responded(new RobotSensorResponse(new RobotState(1, 100, 0, 0, 0, 0, 0, 0, 0, false, 0)
                .withMotorsEnabled(true)));
        assertEquals(0x1f, robot.getFlags());
        assertTrue(robot.areSonarsEnabledLegacy());
        robot.disableSonar();
        assertEquals(0x01, robot.getFlags());
        robot.enableAutonomousDrivingSonar();
        assertTrue(robot.areAutonomousDrivingSonarsEnabled());
        assertFalse(robot.areSonarsEnabled());
        assertEquals(new Command.SetSonar(true), robot.last());
        robot.enableSonar();
        assertFalse(robot.areAutonomousDrivingSonarsEnabled());
        assertFalse(robot.isEStopPressed());
        assertFalse(robot.getEstop());
        assertFalse(robot.hasFaultFlags());
        assertFalse(robot.hasFlags3());
        assertFalse(robot.hasTableSensingIR());
        assertFalse(robot.isLeftBreakBeamTriggered());
    }

    @Test
    void chargeStateAndChargerPowerAreUnknownUntilAProgramSetsThem() {
        ArRobot robot = Cycles.p3dxRobot();
        assertEquals(ArRobot.ChargeState.CHARGING_UNKNOWN, robot.getChargeState());
        assertEquals("Unknown", robot.getChargeStateName());
        assertEquals(255, robot.getChargeState().code());
        robot.setChargeState(ArRobot.ChargeState.CHARGING_BULK);
        assertEquals("Bulk", robot.getChargeStateName());
        assertFalse(robot.isChargerPowerGood());
        robot.setIsChargerPowerGood(true);
        assertTrue(robot.isChargerPowerGood());
        assertFalse(robot.hasTemperature());
        assertEquals(-128, robot.getTemperature());
    }

    @Test
    void aStateOfChargeSetIsHeldUntilAReadingReplacesIt() {
        ArRobot robot = Cycles.p3dxRobot();
        assertFalse(robot.haveStateOfCharge());
        robot.setStateOfCharge(80);
        assertTrue(robot.haveStateOfCharge());
        assertEquals(80, robot.getStateOfCharge());
        robot.responded(new RobotSensorResponse(new RobotState(1, 500, 0, 0, 0, 0, 0, 0, 0, false, 0)
                .with(BatteryReading.PART, new BatteryReading(12.5, 60))));
        assertEquals(60, robot.getStateOfCharge());
        assertEquals(500, robot.getStateOfChargeSetTime().getTimeMs());
    }

    @Test
    void ignoringTheMicrocontrollerLeavesTheBatteryToSetBatteryInfo() {
        ArRobot robot = Cycles.p3dxRobot();
        robot.setIgnoreMicroControllerBatteryInfo(true);
        robot.responded(new RobotSensorResponse(new RobotState(1, 100, 0, 0, 0, 0, 0, 0, 0, false, 0)
                .with(BatteryReading.PART, new BatteryReading(11, 50))));
        assertEquals(13, robot.getBatteryVoltageNow(), "ARIA's value before any reading");
        robot.setBatteryInfo(25.5, 12.75, true, 70);
        assertEquals(25.5, robot.getRealBatteryVoltageNow());
        assertEquals(12.75, robot.getBatteryVoltageNow());
        assertEquals(70, robot.getStateOfCharge());
    }

    @Test
    void theIdentityComesFromTheParameters() {
        ArRobot robot = new ArRobot("scout1", "127.0.0.1", 5000, "p3dx");
        assertEquals("scout1", robot.getRobotName());
        assertEquals("Pioneer", robot.getRobotType());
        assertEquals("p3dx", robot.getRobotSubType());
        assertSame(robot.getParameters(), robot.getRobotParams());
        assertEquals("SIM", robot.getRobotSerialNumber());
        robot.setAbsoluteMaxTransVel(300);
        robot.setName("other");
        assertEquals("other", robot.getName());
        assertEquals(300, robot.getAbsoluteMaxTransVel(), "a rename keeps the limits");
        assertTrue(robot.loadParamFile("p3at"));
        assertEquals("p3at", robot.getRobotSubType());
        assertEquals(16, robot.getNumSonar());
        try (CapturedLog log = new CapturedLog("robosim.aria")) {
            assertFalse(robot.loadParamFile("no-such-robot"));
            assertTrue(log.lines().stream().anyMatch(l -> l.contains("loadParamFile")), log.lines().toString());
        }
        assertEquals("p3at", robot.getRobotSubType());
    }

    @Test
    void sonarBoardsFollowAriasRules() {
        ArRobot robot = Cycles.p3dxRobot();
        ArSonarDevice a = new ArSonarDevice();
        ArSonarDevice b = new ArSonarDevice();
        assertFalse(robot.addSonar(null, 1));
        assertTrue(robot.addSonar(a, 1));
        assertTrue(robot.addSonar(a, 1), "the same board again is fine");
        assertFalse(robot.addSonar(b, 1), "another board of that number is refused");
        assertTrue(robot.addSonar(b, 2));
        assertSame(a, robot.findSonar(1));
        assertEquals(List.of(1, 2), List.copyOf(robot.getSonarMap().keySet()));
        assertTrue(robot.hasSonar(b));
        assertFalse(robot.remSonar(3));
        assertTrue(robot.remSonar(a));
        assertFalse(robot.remSonar(a));
        assertNull(robot.findSonar(1));
    }

    @Test
    void rangeDevicesAreFoundAndRemovedByName() {
        ArRobot robot = Cycles.p3dxRobot();
        ArSonarDevice d = new ArSonarDevice();
        robot.addRangeDevice(d);
        assertTrue(robot.hasRangeDevice(d));
        assertEquals(List.of(d), robot.getRangeDevices());
        robot.remRangeDevice(d.getName());
        assertFalse(robot.hasRangeDevice(d));
    }

    @Test
    void tryingToMoveFollowsTheCommandsAndForceLastsTheCycle() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        robot.cycleWheels(0, 0, 0, 0, 0);
        assertFalse(robot.isTryingToMove());
        robot.setVel(100);
        assertTrue(robot.isTryingToMove());
        robot.setVel(0.4);
        assertFalse(robot.isTryingToMove(), "ARIA's 0.5 mm/s");
        robot.setRotVel(10);
        assertTrue(robot.isTryingToMove());
        robot.stop();
        assertFalse(robot.isTryingToMove());
        robot.setHeading(90);
        assertTrue(robot.isTryingToMove());
        robot.cycleWheels(0, 0, 89.5, 0, 0);
        assertFalse(robot.isTryingToMove(), "within ARIA's 1 degree");
        robot.forceTryingToMove();
        assertTrue(robot.isTryingToMove());
        robot.cycleWheels(0, 0, 89.5, 0, 0);
        assertFalse(robot.isTryingToMove(), "the force lasts until the end of the cycle");
    }

    @Test
    void theWheelEncodersCountOnlyOnceRequested() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        double mmPerTick = RobotParameterFiles.conversionFactors("p3dx").distConvFactor();
        robot.cycleWheels(0, 0, 0, 100, 200);
        robot.cycleWheels(0, 0, 0, 100, 200);
        assertEquals(0, robot.getLeftEncoder());
        robot.requestEncoderPackets();
        assertTrue(robot.haveRequestedEncoderPackets());
        for (int i = 0; i < 10; i++) {
            robot.cycleWheels(0, 0, 0, 100, 200);
        }
        assertEquals(Math.round(100 / mmPerTick), robot.getLeftEncoder());
        assertEquals(Math.round(200 / mmPerTick), robot.getRightEncoder());
        robot.stopEncoderPackets();
        robot.cycleWheels(0, 0, 0, 100, 200);
        assertEquals(Math.round(100 / mmPerTick), robot.getLeftEncoder());
    }

    @Test
    void ioAndOdometerUnitsAnswerAsAriaDoes() {
        ArRobot robot = Cycles.p3dxRobot();
        assertFalse(robot.haveRequestedIOPackets());
        robot.requestIOPackets();
        assertTrue(robot.haveRequestedIOPackets());
        assertEquals(0, robot.getIOAnalogSize());
        assertEquals(0, robot.getIODigIn(0));
        Cycles.cycle(robot, 100, 0, 0, 0);
        Cycles.cycle(robot, 90_100, 1500, 0, 0);
        assertEquals(1.5, robot.getOdometerDistanceMeters(), 1e-9);
        assertEquals(1.5, robot.getOdometerTimeMinutes(), 1e-9);
        assertEquals(500, robot.getStateReflectionRefreshTime());
        robot.setStateReflectionRefreshTime(-1);
        assertEquals(0, robot.getStateReflectionRefreshTime());
    }

    @Test
    void theLoggingTogglesLogWhatTheySay() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        ArRobot sending = Cycles.p3dxRobot(); // ConnectedRobot keeps its requests instead of sending them
        try (CapturedLog log = new CapturedLog("robosim.aria")) {
            sending.setLogMovementSent(true);
            sending.setVel(120);
            assertTrue(log.lines().stream().anyMatch(l -> l.contains("sent") && l.contains("120")), log.lines().toString());
            log.clear();
            robot.setLogVelocitiesReceived(true);
            robot.cycleWheels(0, 0, 0, 50, 50);
            assertTrue(log.lines().stream().anyMatch(l -> l.contains("vel 50")), log.lines().toString());
        }
        assertTrue(sending.getLogMovementSent());
        assertFalse(robot.getLogMovementSent());
        assertFalse(robot.getLogSIPContents());
    }
}
