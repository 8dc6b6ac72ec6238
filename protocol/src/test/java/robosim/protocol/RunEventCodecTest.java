package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.params.provider.Arguments.arguments;

import com.fasterxml.jackson.dataformat.smile.databind.SmileMapper;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.MethodSource;
import robosim.protocol.MessageCodec.Format;

/**
 * A robot's metrics and its request to end the run on the wire: they round-trip in its requests and
 * in the snapshots, and a frame whose values break their rules is an invalid value, as any other.
 */
class RunEventCodecTest {
    private static final MessageCodec JSON = new MessageCodec(Format.JSON);
    private static final String NAME_RULE = "was supplied for a metric's name: a letter, then up to 63 letters,"
            + " digits, '_', '.' or '-'";

    private static byte[] json(String text) {
        return text.getBytes(StandardCharsets.UTF_8);
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void metricsAndAnEndRequestRoundTripInARobotsRequests(Format format) throws FrameException {
        MessageCodec codec = new MessageCodec(format);
        RobotRequests requests = new RobotRequests(812, List.of(new Command.ReportMetric("cellsExplored", 57),
                new Command.ReportMetric("gold.distance_mm", -1.5e-3), new Command.EndRun("gold found")));

        assertEquals(requests, codec.decode(codec.encode(requests)));
    }

    @Test
    void aHandWrittenFrameDecodesToTheCommands() throws FrameException {
        byte[] frame = json("{\"type\":\"robotRequests\",\"step\":9,\"commands\":[{\"cmd\":\"metric\","
                + "\"name\":\"cells\",\"value\":12},{\"cmd\":\"endRun\",\"reason\":\"done exploring\"}]}");

        assertEquals(new RobotRequests(9, List.of(new Command.ReportMetric("cells", 12),
                new Command.EndRun("done exploring"))), JSON.decode(frame));
    }

    static Stream<Arguments> brokenCommands() {
        return Stream.of(
                arguments("{\"cmd\":\"metric\",\"name\":\"9lives\",\"value\":1}", "'9lives' " + NAME_RULE),
                arguments("{\"cmd\":\"metric\",\"name\":\"a b\",\"value\":1}", "'a b' " + NAME_RULE),
                arguments("{\"cmd\":\"metric\",\"value\":1}", "null " + NAME_RULE),
                arguments("{\"cmd\":\"endRun\",\"reason\":\"\"}",
                        "a reason of 0 characters was supplied for ending the run: 1 to 200 characters"),
                arguments("{\"cmd\":\"endRun\"}", "null was supplied for ending the run: 1 to 200 characters"),
                arguments("{\"cmd\":\"endRun\",\"reason\":\"found\\u0007it\"}",
                        "a reason with the control character U+0007 at index 5 was supplied for ending the run: it is"
                                + " one line of text"),
                arguments("{\"cmd\":\"endRun\",\"reason\":\"" + "x".repeat(201) + "\"}",
                        "a reason of 201 characters was supplied for ending the run: 1 to 200 characters"));
    }

    @ParameterizedTest
    @MethodSource("brokenCommands")
    void aCommandFromTheWireThatBreaksItsRuleIsAnInvalidValue(String command, String rule) {
        byte[] frame = json("{\"type\":\"robotRequests\",\"step\":3,\"commands\":[" + command + "]}");

        InvalidValueException e = assertThrows(InvalidValueException.class, () -> JSON.decode(frame));

        assertEquals(rule, e.getMessage());
    }

    /** JSON has no NaN, Smile has: a robot's Smile frame can carry one. */
    @Test
    void aNonFiniteMetricFromTheWireIsAnInvalidValue() throws Exception {
        Map<String, Object> metric = new LinkedHashMap<>();
        metric.put("cmd", "metric");
        metric.put("name", "cells");
        metric.put("value", Double.POSITIVE_INFINITY);
        Map<String, Object> requests = new LinkedHashMap<>();
        requests.put("type", "robotRequests");
        requests.put("step", 2);
        requests.put("commands", List.of(metric));
        byte[] payload = new SmileMapper().writeValueAsBytes(requests);

        InvalidValueException e = assertThrows(InvalidValueException.class, () -> new MessageCodec().decode(payload));

        assertEquals("Infinity was supplied for metric cells: it must be a finite number", e.getMessage());
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void aSnapshotCarriesTheStepsMetricsAndTheEndRequest(Format format) throws FrameException {
        MessageCodec codec = new MessageCodec(format);
        Snapshot snapshot = Messages.snapshot();

        Snapshot back = (Snapshot) codec.decode(codec.encode(snapshot));

        assertEquals(List.of(new Snapshot.Metric("robot1", "cellsExplored", 37.5),
                new Snapshot.Metric("robot2", "gold.distance", -0.25)), back.metrics());
        assertEquals(new Snapshot.EndRequest("robot1", 42, "gold found ✓"), back.endRequest());
    }

    @Test
    void aSnapshotWithoutThemLeavesThemOutAsSnapshotsBeforeThemDid() throws FrameException {
        Snapshot plain = new Snapshot(5, 500, List.of());

        String json = new String(JSON.encode(plain), StandardCharsets.UTF_8);

        assertFalse(json.contains("metrics"), json);
        assertFalse(json.contains("endRequest"), json);
    }

    @Test
    void aSnapshotWrittenBeforeMetricsReadsAsOneWithNone() throws FrameException {
        byte[] old = json("{\"type\":\"frame\",\"step\":5,\"timeMs\":500,\"robots\":[],\"messages\":[],\"said\":[],"
                + "\"events\":[]}");

        Snapshot back = (Snapshot) JSON.decode(old);

        assertEquals(List.of(), back.metrics());
        assertNull(back.endRequest());
    }

    static Stream<Arguments> brokenMetrics() {
        return Stream.of(
                arguments("{\"robot\":\"r1\",\"name\":\"-x\",\"value\":1}", "'-x' " + NAME_RULE),
                arguments("{\"robot\":\"\",\"name\":\"x\",\"value\":1}", "metric x needs the robot that reported it"));
    }

    @ParameterizedTest
    @MethodSource("brokenMetrics")
    void aSnapshotsMetricThatBreaksTheRuleIsAnInvalidValue(String metric, String rule) {
        byte[] frame = json("{\"type\":\"frame\",\"step\":5,\"timeMs\":500,\"robots\":[],\"metrics\":["
                + metric + "]}");

        InvalidValueException e = assertThrows(InvalidValueException.class, () -> JSON.decode(frame));

        assertEquals(rule, e.getMessage());
    }

    @Test
    void aSnapshotsEndRequestThatBreaksTheRuleIsAnInvalidValue() {
        byte[] frame = json("{\"type\":\"frame\",\"step\":5,\"timeMs\":500,\"robots\":[],"
                + "\"endRequest\":{\"robot\":\"r1\",\"step\":0,\"reason\":\"done\"}}");

        InvalidValueException e = assertThrows(InvalidValueException.class, () -> JSON.decode(frame));

        assertTrue(e.getMessage().startsWith("0 was supplied for the step of robot r1's request to end the run"),
                e.getMessage());
    }
}
