package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Named.named;
import static org.junit.jupiter.params.provider.Arguments.arguments;

import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import robosim.protocol.Command.Addressing;

/** Each command refuses, as it is made, a value that breaks its rule, and says which rule. */
class CommandTest {

    static Stream<Arguments> brokenRules() {
        return Stream.of(
                refused("SetVel(NaN)", () -> new Command.SetVel(Double.NaN),
                        "NaN was supplied for vel: it must be a finite number"),
                refused("SetRotVel(Infinity)", () -> new Command.SetRotVel(Double.POSITIVE_INFINITY),
                        "Infinity was supplied for rotVel: it must be a finite number"),
                refused("SetVel2(NaN, 0)", () -> new Command.SetVel2(Double.NaN, 0),
                        "NaN was supplied for left: it must be a finite number"),
                refused("SetVel2(0, -Infinity)", () -> new Command.SetVel2(0, Double.NEGATIVE_INFINITY),
                        "-Infinity was supplied for right: it must be a finite number"),
                refused("Move(NaN)", () -> new Command.Move(Double.NaN),
                        "NaN was supplied for distance: it must be a finite number"),
                refused("SetHeading(NaN)", () -> new Command.SetHeading(Double.NaN),
                        "NaN was supplied for heading: it must be a finite number"),
                refused("SetDeltaHeading(Infinity)", () -> new Command.SetDeltaHeading(Double.POSITIVE_INFINITY),
                        "Infinity was supplied for delta: it must be a finite number"),
                refused("SetMaxTransVel(NaN)", () -> new Command.SetMaxTransVel(Double.NaN),
                        "NaN was supplied for maxVel: it must be a finite number"),
                refused("SetMaxRotVel(NaN)", () -> new Command.SetMaxRotVel(Double.NaN),
                        "NaN was supplied for maxRotVel: it must be a finite number"),
                refused("MoveWheels(Infinity, 0)", () -> new Command.MoveWheels(Double.POSITIVE_INFINITY, 0),
                        "Infinity was supplied for left: it must be a finite number"),
                refused("MoveWheels(0, NaN)", () -> new Command.MoveWheels(0, Double.NaN),
                        "NaN was supplied for right: it must be a finite number"),
                refused("SetAccel(0, 60)", () -> new Command.SetAccel(0, 60),
                        "0.0 was supplied for trans accel: it must be greater than 0"),
                refused("SetAccel(250, -1)", () -> new Command.SetAccel(250, -1),
                        "-1.0 was supplied for rot accel: it must be greater than 0"),
                refused("SetAccel(250, Infinity)", () -> new Command.SetAccel(250, Double.POSITIVE_INFINITY),
                        "Infinity was supplied for rot accel: it must be greater than 0"),
                refused("ConfigureLaser(increment 0.25)", () -> new Command.ConfigureLaser(true, 0.25, 8000),
                        "0.25 was supplied for the laser increment: a SICK LMS200 scans at 1 or 0.5 degrees"),
                refused("ConfigureLaser(increment NaN)", () -> new Command.ConfigureLaser(false, Double.NaN, 8000),
                        "NaN was supplied for the laser increment: a SICK LMS200 scans at 1 or 0.5 degrees"),
                refused("ConfigureLaser(range 0)", () -> new Command.ConfigureLaser(true, 1, 0),
                        "0.0 was supplied for laser maxRange: it must be greater than 0"),
                refused("ConfigureHeatSensor(field 0)", () -> new Command.ConfigureHeatSensor(true, 0, 4000),
                        "0.0 was supplied for heat fieldOfView: it must be greater than 0"),
                refused("ConfigureHeatSensor(range NaN)", () -> new Command.ConfigureHeatSensor(true, 60, Double.NaN),
                        "NaN was supplied for heat maxRange: it must be greater than 0"),
                refused("ConfigureHeatSensor(field 361)", () -> new Command.ConfigureHeatSensor(true, 361, 4000),
                        "361.0 was supplied for heat fieldOfView: at most 360 degrees"),
                refused("SendMessage(no mode)", () -> new Command.SendMessage(3, null, "b", "text", "hi"),
                        "message 3 needs a mode, a kind and a body"),
                refused("SendMessage(no kind)", () -> new Command.SendMessage(4, Addressing.ALL, null, null, "hi"),
                        "message 4 needs a mode, a kind and a body"),
                refused("SendMessage(no body)", () -> new Command.SendMessage(5, Addressing.ROBOT, "b", "text", null),
                        "message 5 needs a mode, a kind and a body"),
                refused("SendMessage(to no robot)",
                        () -> new Command.SendMessage(6, Addressing.ROBOT, null, "text", "hi"),
                        "message 6 is addressed to a robot but names none"),
                refused("SendMessage(to a blank group)",
                        () -> new Command.SendMessage(7, Addressing.GROUP, " ", "text", "hi"),
                        "message 7 is addressed to a group but names none"),
                refused("JoinGroup(blank)", () -> new Command.JoinGroup(""),
                        "a group to join needs a name"),
                refused("LeaveGroup(null)", () -> new Command.LeaveGroup(null),
                        "a group to leave needs a name"),
                refused("ReportFound(blank)", () -> new Command.ReportFound("  "),
                        "a report of a find needs the object's name"),
                refused("Say(null)", () -> new Command.Say(null),
                        "a robot says at most 1000 characters, not nothing"),
                refused("Say(1001 characters)", () -> new Command.Say("x".repeat(1001)),
                        "a robot says at most 1000 characters, not 1001"),
                refused("ReportMetric(null name)", () -> new Command.ReportMetric(null, 1),
                        "null was supplied for a metric's name: a letter, then up to 63 letters, digits, '_', '.' or"
                                + " '-'"),
                refused("ReportMetric(empty name)", () -> new Command.ReportMetric("", 1),
                        "'' was supplied for a metric's name: a letter, then up to 63 letters, digits, '_', '.' or"
                                + " '-'"),
                refused("ReportMetric(name starting with a digit)", () -> new Command.ReportMetric("2nd", 1),
                        "'2nd' was supplied for a metric's name: a letter, then up to 63 letters, digits, '_', '.' or"
                                + " '-'"),
                refused("ReportMetric(name with a space)", () -> new Command.ReportMetric("cells explored", 1),
                        "'cells explored' was supplied for a metric's name: a letter, then up to 63 letters, digits,"
                                + " '_', '.' or '-'"),
                refused("ReportMetric(name of 65 characters)", () -> new Command.ReportMetric("m".repeat(65), 1),
                        "a name of 65 characters was supplied for a metric's name: a letter, then up to 63 letters,"
                                + " digits, '_', '.' or '-'"),
                refused("ReportMetric(NaN)", () -> new Command.ReportMetric("cells", Double.NaN),
                        "NaN was supplied for metric cells: it must be a finite number"),
                refused("ReportMetric(-Infinity)", () -> new Command.ReportMetric("cells", Double.NEGATIVE_INFINITY),
                        "-Infinity was supplied for metric cells: it must be a finite number"),
                refused("EndRun(null)", () -> new Command.EndRun(null),
                        "null was supplied for ending the run: 1 to 200 characters"),
                refused("EndRun(empty)", () -> new Command.EndRun(""),
                        "a reason of 0 characters was supplied for ending the run: 1 to 200 characters"),
                refused("EndRun(201 characters)", () -> new Command.EndRun("x".repeat(201)),
                        "a reason of 201 characters was supplied for ending the run: 1 to 200 characters"),
                refused("EndRun(a line break)", () -> new Command.EndRun("gold\nfound"),
                        "a reason with the control character U+000A at index 4 was supplied for ending the run: it is"
                                + " one line of text"),
                refused("EndRun(a C1 control)", () -> new Command.EndRun("gold\u0085"),
                        "a reason with the control character U+0085 at index 4 was supplied for ending the run: it is"
                                + " one line of text"));
    }

    private static Arguments refused(String what, Executable make, String rule) {
        return arguments(named(what, make), rule);
    }

    @ParameterizedTest
    @MethodSource("brokenRules")
    void aValueThatBreaksARuleIsRefusedNamingIt(Executable make, String rule) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, make);

        assertEquals(rule, e.getMessage());
    }

    @Test
    void valuesAtTheEdgeOfTheirRulesAreAccepted() {
        assertDoesNotThrow(() -> new Command.ConfigureLaser(true, 1, 8000));
        assertDoesNotThrow(() -> new Command.ConfigureHeatSensor(true, 360, 1));
        assertDoesNotThrow(() -> new Command.SendMessage(1, Addressing.ALL, null, "text", ""));
        assertDoesNotThrow(() -> new Command.Say("x".repeat(1000)));
        assertDoesNotThrow(() -> new Command.SetVel(-Double.MAX_VALUE));
        assertDoesNotThrow(() -> new Command.SetAccel(Double.MIN_VALUE, Double.MIN_VALUE));
        assertDoesNotThrow(() -> new Command.ReportMetric("m", -Double.MAX_VALUE));
        assertDoesNotThrow(() -> new Command.ReportMetric("m" + "a1_.-".repeat(12) + "xyz", 0));
        assertDoesNotThrow(() -> new Command.EndRun("x"));
        assertDoesNotThrow(() -> new Command.EndRun("gold found ✓ ".repeat(15) + "x".repeat(5)));
    }
}
