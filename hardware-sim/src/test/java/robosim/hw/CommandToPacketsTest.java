package robosim.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HexFormat;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import robosim.params.ConversionFactors;
import robosim.pioneer.PioneerPacket;
import robosim.protocol.Command;

/** The robot's commands become the bytes ARIA sends a Pioneer for them; what the protocol cannot carry is said once. */
class CommandToPacketsTest {
    private final CommandToPackets to = new CommandToPackets(new ConversionFactors(0.001534, 0.485, 1, 1, 0.0056, 20),
            "127.0.0.1:8101");

    private String hex(Command c) {
        return to.packets(c).stream().map(PioneerPacket::encode).map(b -> HexFormat.of().formatHex(b))
                .collect(Collectors.joining(" "));
    }

    @Test
    void aNegativeVelocityIsVelWithANegativeArgument() {
        assertEquals("fafb060b1bc800d31b", hex(new Command.SetVel(-200)));
    }

    @Test
    void wheelVelocitiesAreVel2InUnitsOfTheDivisorLeftInTheHighByte() {
        assertEquals("fafb06203b0a052a40", hex(new Command.SetVel2(100, 200)));
    }

    @Test
    void aNegativeHeadingIsSentAsAPioneersZeroTo359() {
        assertEquals("fafb060c3b0e011a3c", hex(new Command.SetHeading(-90)));
    }

    @Test
    void moveIsMoveInMm() {
        assertEquals("fafb06083be803f03e", hex(new Command.Move(1000)));
    }

    @Test
    void aDecelerationLimitIsSetraWithANegativeArgument() {
        assertEquals("fafb06171b3200491b", hex(new Command.SetDriveLimit(Command.DriveLimit.ROT_DECEL, 50)));
    }

    @Test
    void theMotorSwitchIsEnableOneOrZeroAsAriasEnableMotorsSendsIt() {
        assertEquals("fafb06043b0100053b", hex(new Command.SetMotors(true)));
        assertEquals("fafb06043b0000043b", hex(new Command.SetMotors(false)));
    }

    @Test
    void stopIsStopWithoutArgument() {
        assertEquals("fafb031d001d", hex(new Command.Stop()));
    }

    @Test
    void theLaserIsConfiguredAsAriasSimulatedLaserDoesIt() {
        List<PioneerPacket> p = to.packets(new Command.ConfigureLaser(true, 0.5, 8000));
        assertEquals(List.of(36, 37, 38, 35), p.stream().map(PioneerPacket::id).toList());
        assertEquals(List.of(-90, 90, 50, 2), p.stream().map(q -> q.reader().intArgument("a")).toList());
        assertEquals("fafb06233b0000233b", hex(new Command.ConfigureLaser(false, 1, 8000)));
    }

    @Test
    void sayIsASimMessage() {
        PioneerPacket p = to.packets(new Command.Say("hi")).get(0);
        assertEquals(238, p.id());
        assertEquals("hi", p.reader().stringArgument("text"));
    }

    @Test
    void messagingIsAnErrorOnceForEachKindAndSendsNothing() {
        assertTrue(to.packets(new Command.SendMessage(1, Command.Addressing.ALL, null, "text", "a")).isEmpty());
        to.packets(new Command.SendMessage(2, Command.Addressing.ALL, null, "text", "b"));
        to.packets(new Command.JoinGroup("g"));
        List<String> errors = to.takeErrors();
        assertEquals(2, errors.size(), errors.toString());
        assertTrue(errors.get(0).startsWith("SendMessage was not carried out: the robot server at 127.0.0.1:8101"),
                errors.get(0));
        assertTrue(errors.get(1).startsWith("JoinGroup"), errors.get(1));
        assertTrue(to.takeErrors().isEmpty(), "taken");
    }

    @Test
    void theHeatSensorIsAnError() {
        to.packets(new Command.ConfigureHeatSensor(true, 90, 3000));
        assertTrue(to.takeErrors().get(0).contains("no heat sensor"));
    }

    @Test
    void aDrawingIsRefusedOnceAndSendsNothing() {
        Command.Draw draw = new Command.Draw("map", List.of());
        assertTrue(to.packets(draw).isEmpty());
        assertTrue(to.packets(draw).isEmpty());
        List<String> errors = to.takeErrors();
        assertEquals(1, errors.size(), errors.toString());
        assertTrue(errors.get(0).startsWith("Draw was not carried out"), errors.get(0));
    }

    @Test
    void aMetricAndAnEndRequestAreRefusedSayingWhatThePioneerProtocolLacks() {
        assertTrue(to.packets(new Command.ReportMetric("cells", 3)).isEmpty());
        assertTrue(to.packets(new Command.EndRun("done")).isEmpty());
        List<String> errors = to.takeErrors();
        assertEquals(2, errors.size(), errors.toString());
        assertTrue(errors.get(0).startsWith("ReportMetric was not carried out") && errors.get(0).contains(
                "which has no metrics for the run's results"), errors.get(0));
        assertTrue(errors.get(1).startsWith("EndRun was not carried out") && errors.get(1).contains(
                "which has no request to end the run"), errors.get(1));
    }

    @Test
    void theCameraIsRefusedNamingTheAuxPort() {
        assertTrue(to.packets(new Command.ConfigurePtz(robosim.protocol.PtzModel.VCC4, 300)).isEmpty());
        assertTrue(to.packets(new Command.AimPtz(10, 0, 0)).isEmpty());
        List<String> errors = to.takeErrors();
        assertEquals(2, errors.size(), errors.toString());
        assertTrue(errors.get(0).startsWith("ConfigurePtz was not carried out"), errors.get(0));
        assertTrue(errors.get(1).contains("AUX serial port"), errors.get(1));
    }
}
