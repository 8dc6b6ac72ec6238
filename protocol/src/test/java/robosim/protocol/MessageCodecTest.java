package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.protocol.RecordAssert.assertDeepEquals;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.dataformat.smile.SmileFactory;
import com.fasterxml.jackson.dataformat.smile.databind.SmileMapper;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.EnumSource;
import org.opentest4j.AssertionFailedError;
import robosim.protocol.MessageCodec.Format;

class MessageCodecTest {

    private static Message roundTrip(Format format, Message message) throws FrameException {
        MessageCodec codec = new MessageCodec(format);
        return codec.decode(codec.encode(message));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void robotHelloRoundTripsWithItsParameters(Format format) throws FrameException {
        RobotHello hello = Messages.robotHello();

        assertEquals(hello, roundTrip(format, hello));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void welcomeRoundTripsWithItsState(Format format) throws FrameException {
        Welcome welcome = Messages.welcome();

        assertDeepEquals(welcome, roundTrip(format, welcome));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void timeStepRoundTripsTheStateAndItsSonarArray(Format format) throws FrameException {
        TimeStep step = Messages.timeStep();

        TimeStep decoded = (TimeStep) roundTrip(format, step);

        assertDeepEquals(step, decoded);
        assertArrayEquals(new int[] {5000, 4890, 2311, 742, 739, 2200, 5000, 4999, 3010, 2875, 118, 101, 4400,
                4301, 650, 640}, decoded.state().get(SonarReading.PART).ranges());
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void robotRequestsRoundTripEveryCommandSubtypeInOrder(Format format) throws FrameException {
        RobotRequests requests = Messages.robotRequests();

        assertEquals(requests, roundTrip(format, requests));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void robotRequestsWithNoCommandsRoundTrip(Format format) throws FrameException {
        RobotRequests yielded = new RobotRequests(7, List.of());

        assertEquals(yielded, roundTrip(format, yielded));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void viewerHelloRoundTrips(Format format) throws FrameException {
        ViewerHello hello = Messages.viewerHello();

        assertEquals(hello, roundTrip(format, hello));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void worldDescriptionRoundTripsObstaclesAndRobots(Format format) throws FrameException {
        WorldDescription world = Messages.worldDescription();

        assertDeepEquals(world, roundTrip(format, world));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void worldDescriptionRoundTripsAMapsOriginAndZones(Format format) throws FrameException {
        WorldDescription map = new WorldDescription("lab", 10000, 8000, 100, List.of(), List.of(), List.of(),
                -4000, -3000, List.of(new WorldDescription.Zone(true, new double[] {0, 0, 10, 0, 10, 10, 0, 10}, "keep out")));

        assertDeepEquals(map, roundTrip(format, map));
    }

    @Test
    void aWorldDescriptionWithoutOriginOrZonesReadsAsAWorldFromZero() throws FrameException {
        // as recordings made before maps hold it
        String old = "{\"type\":\"world\",\"name\":\"w\",\"width\":100.0,\"height\":50.0,\"stepMs\":100,"
                + "\"obstacles\":[],\"robots\":[],\"heat\":[]}";
        WorldDescription w = (WorldDescription) new MessageCodec(Format.JSON).decode(old.getBytes(StandardCharsets.UTF_8));

        assertEquals(List.of(0.0, 0.0, List.of()), List.of(w.minX(), w.minY(), w.zones()));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void worldDescriptionRoundTripsObstacleColoursAndTheGold(Format format) throws FrameException {
        WorldDescription world = new WorldDescription("c", 6000, 6000, 100,
                List.of(new WorldDescription.Obstacle(new double[] {0, 0, 10, 0, 10, 10}, 300, "red")), List.of(),
                List.of(new WorldDescription.HeatSource(100, 200, 20), new WorldDescription.HeatSource(300, 400, 50, true)));

        WorldDescription back = (WorldDescription) roundTrip(format, world);

        assertEquals("red", back.obstacles().get(0).color());
        assertEquals(List.of(false, true), back.heat().stream().map(WorldDescription.HeatSource::gold).toList());
    }

    @Test
    void aWorldDescriptionWithoutColoursOrGoldReadsAsPlainObstaclesAndHeat() throws FrameException {
        // as recordings made before obstacles' colours and the gold were sent hold it
        String old = "{\"type\":\"world\",\"name\":\"w\",\"width\":100.0,\"height\":50.0,\"stepMs\":100,"
                + "\"obstacles\":[{\"xy\":[0,0,10,0,10,10],\"height\":300}],\"robots\":[],"
                + "\"heat\":[{\"x\":1,\"y\":2,\"intensity\":3}]}";
        WorldDescription w = (WorldDescription) new MessageCodec(Format.JSON).decode(old.getBytes(StandardCharsets.UTF_8));

        assertEquals(null, w.obstacles().get(0).color());
        assertEquals(false, w.heat().get(0).gold());
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void snapshotRoundTripsEveryRobotView(Format format) throws FrameException {
        Snapshot snapshot = Messages.snapshot();

        assertDeepEquals(snapshot, roundTrip(format, snapshot));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void byeRoundTrips(Format format) throws FrameException {
        Bye bye = Messages.bye();

        assertEquals(bye, roundTrip(format, bye));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void byeNamingOneRobotOfASharedLinkRoundTrips(Format format) throws FrameException {
        Bye bye = new Bye("refused: robot robot1 is already connected", "robot1");

        assertEquals(bye, roundTrip(format, bye));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void linkMessagesRoundTripEveryRobotsPart(Format format) throws FrameException {
        assertEquals(Messages.linkHello(), roundTrip(format, Messages.linkHello()));
        assertDeepEquals(Messages.timeSteps(), roundTrip(format, Messages.timeSteps()));
        assertEquals(Messages.linkRequests(), roundTrip(format, Messages.linkRequests()));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void helloesRoundTripTheirSecretAndNeverPrintIt(Format format) throws FrameException {
        List<Message> hellos = List.of(Messages.robotHello(), Messages.linkHello(), Messages.controlHello(),
                new ViewerHello("v", Messages.SECRET));
        for (Message m : hellos) {
            assertEquals(m, roundTrip(format, m));
            assertFalse(m.toString().contains(Messages.SECRET), m.toString());
        }
        // a hello without a secret has no token on the wire at all
        assertEquals(new ViewerHello("v"), roundTrip(format, new ViewerHello("v")));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void keepAliveRoundTripsWithItsStep(Format format) throws FrameException {
        assertEquals(new KeepAlive(42), roundTrip(format, Messages.keepAlive()));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void controlMessagesRoundTripTheirArgumentsAndAnswer(Format format) throws FrameException {
        assertEquals(Messages.controlRequest(), roundTrip(format, Messages.controlRequest()));
        assertEquals(Messages.controlReply(), roundTrip(format, Messages.controlReply()));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void runStatusRoundTripsEveryRobotsRow(Format format) throws FrameException {
        assertEquals(Messages.runStatus(), roundTrip(format, Messages.runStatus()));
    }

    @Test
    void runStatusWithANegativeCountIsAnInvalidValue() {
        byte[] payload = ("{\"type\":\"runStatus\",\"id\":1,\"world\":\"w\",\"step\":3,\"timeMs\":300,"
                + "\"paused\":false,\"pace\":0,\"robots\":[{\"name\":\"r1\",\"type\":\"p3dx\","
                + "\"drivenBy\":\"\",\"connected\":true,\"x\":0,\"y\":0,\"th\":0,\"vel\":0,\"rotVel\":0,"
                + "\"stalled\":false,\"collisions\":-1,\"sent\":0,\"received\":0,\"lastStep\":0}]}")
                .getBytes(StandardCharsets.UTF_8);

        InvalidValueException e = assertThrows(InvalidValueException.class,
                () -> new MessageCodec(Format.JSON).decode(payload));

        assertTrue(e.getMessage().contains("robot r1's status holds a negative count: -1"), e.getMessage());
    }

    @Test
    void controlRequestWithoutArgumentsOnTheWireHasNone() throws FrameException {
        MessageCodec json = new MessageCodec(Format.JSON);

        Message m = json.decode("{\"type\":\"controlRequest\",\"id\":3,\"op\":\"pause\"}".getBytes(StandardCharsets.UTF_8));

        assertEquals(new ControlRequest(3, "pause", List.of()), m);
    }

    @Test
    void controlRequestWithTooManyArgumentsBreaksItsRule() {
        MessageCodec json = new MessageCodec(Format.JSON);
        byte[] payload = ("{\"type\":\"controlRequest\",\"id\":3,\"op\":\"move\",\"args\":"
                + "[\"1\",\"2\",\"3\",\"4\",\"5\",\"6\",\"7\",\"8\",\"9\"]}").getBytes(StandardCharsets.UTF_8);

        InvalidValueException e = assertThrows(InvalidValueException.class, () -> json.decode(payload));

        assertTrue(e.getMessage().contains("at most 8 arguments, got 9"), e.getMessage());
    }

    @Test
    void fixturesHoldOneMessageOfEveryType() {
        Set<Class<?>> covered = Messages.all().stream().map(Object::getClass).collect(Collectors.toSet());

        assertEquals(Set.of(Message.class.getPermittedSubclasses()), covered);
    }

    @Test
    void fixtureRequestsHoldEveryCommandSubtype() {
        Set<Class<?>> covered = Messages.robotRequests().commands().stream().map(Object::getClass)
                .collect(Collectors.toSet());

        assertEquals(commandRecords(), covered);
    }

    /** The records of every group of commands. */
    private static Set<Class<?>> commandRecords() {
        return Arrays.stream(Command.class.getPermittedSubclasses())
                .flatMap(group -> Arrays.stream(group.getPermittedSubclasses())).collect(Collectors.toSet());
    }

    @Test
    void deepComparisonSeesAChangedSonarReading() {
        RobotState s = Messages.state();
        int[] sonar = s.get(SonarReading.PART).ranges().clone();
        sonar[15] = 641;
        RobotState other = s.with(SonarReading.PART, new SonarReading(sonar));

        assertThrows(AssertionFailedError.class,
                () -> assertDeepEquals(new TimeStep(1, 2, s), new TimeStep(1, 2, other)));
    }

    @Test
    void defaultCodecWritesSmile() {
        byte[] payload = new MessageCodec().encode(Messages.bye());

        // Smile's header: ':' ')' '\n'
        assertArrayEquals(new byte[] {0x3A, 0x29, 0x0A}, Arrays.copyOf(payload, 3));
    }

    @Test
    void defaultCodecWritesTheSameBytesAsSmile() {
        TimeStep step = Messages.timeStep();

        assertArrayEquals(new MessageCodec(Format.SMILE).encode(step), new MessageCodec().encode(step));
    }

    @Test
    void smileIsSmallerThanJsonForATimeStep() {
        TimeStep step = Messages.timeStep();

        int smile = new MessageCodec(Format.SMILE).encode(step).length;
        int json = new MessageCodec(Format.JSON).encode(step).length;

        assertTrue(smile < json, "smile " + smile + " bytes, json " + json + " bytes");
    }

    @Test
    void jsonCodecWritesReadableJson() {
        byte[] payload = new MessageCodec(Format.JSON).encode(new Bye("done"));

        assertEquals("{\"type\":\"bye\",\"reason\":\"done\"}", new String(payload, StandardCharsets.UTF_8));
    }

    @ParameterizedTest
    @CsvSource({
        "RobotHello, robotHello",
        "Welcome, welcome",
        "TimeStep, timeStep",
        "RobotRequests, robotRequests",
        "ViewerHello, viewerHello",
        "WorldDescription, world",
        "Snapshot, frame",
        "Bye, bye",
        "LinkHello, linkHello",
        "TimeSteps, timeSteps",
        "LinkRequests, linkRequests",
        "KeepAlive, keepAlive",
        "ControlRequest, controlRequest",
        "ControlReply, controlReply",
        "RunStatus, runStatus",
        "LogLine, logLine",
    })
    void eachMessageTypeKeepsItsWireName(String simpleName, String wireName) {
        Message message = Messages.all().stream().filter(m -> m.getClass().getSimpleName().equals(simpleName))
                .findFirst().orElseThrow();

        String json = new String(new MessageCodec(Format.JSON).encode(message), StandardCharsets.UTF_8);

        assertTrue(json.startsWith("{\"type\":\"" + wireName + "\""), json);
    }

    @Test
    void commandsCarryTheirWireNames() {
        String json = new String(new MessageCodec(Format.JSON).encode(Messages.robotRequests()),
                StandardCharsets.UTF_8);

        assertEquals("{\"type\":\"robotRequests\",\"step\":42,\"commands\":["
                + "{\"cmd\":\"vel\",\"vel\":300.5},"
                + "{\"cmd\":\"rotVel\",\"rotVel\":-15.25},"
                + "{\"cmd\":\"vel2\",\"left\":120.0,\"right\":180.0},"
                + "{\"cmd\":\"move\",\"distance\":-750.0},"
                + "{\"cmd\":\"heading\",\"heading\":135.0},"
                + "{\"cmd\":\"deltaHeading\",\"delta\":-45.5},"
                + "{\"cmd\":\"stop\"},"
                + "{\"cmd\":\"maxVel\",\"vel\":900.0},"
                + "{\"cmd\":\"maxRotVel\",\"rotVel\":90.0},"
                + "{\"cmd\":\"sonar\",\"on\":false},"
                + "{\"cmd\":\"laser\",\"on\":true,\"increment\":0.5,\"maxRange\":8000.0},"
                + "{\"cmd\":\"heatSensor\",\"on\":true,\"fieldOfView\":60.0,\"maxRange\":4000.0},"
                + "{\"cmd\":\"send\",\"id\":5,\"mode\":\"ROBOT\",\"to\":\"robot2\",\"kind\":\"text\",\"body\":\"hi\"},"
                + "{\"cmd\":\"join\",\"group\":\"explorers\"},"
                + "{\"cmd\":\"leave\",\"group\":\"explorers\"},"
                + "{\"cmd\":\"found\",\"object\":\"gold\"},"
                + "{\"cmd\":\"say\",\"text\":\"found it\"},"
                + "{\"cmd\":\"moveWheels\",\"left\":-120.5,\"right\":300.0},"
                + "{\"cmd\":\"accel\",\"trans\":250.0,\"rot\":60.0},"
                + "{\"cmd\":\"driveLimit\",\"limit\":\"TRANS_DECEL\",\"value\":400.0},"
                + "{\"cmd\":\"truePose\",\"x\":-1500.0,\"y\":2500.0,\"th\":90.0},"
                + "{\"cmd\":\"resetToStart\"},"
                + "{\"cmd\":\"reportTruePose\",\"on\":true},"
                + "{\"cmd\":\"gripper\",\"op\":17,\"value\":-25},"
                + "{\"cmd\":\"ptz\",\"model\":\"SONY\",\"mountHeight\":420.0},"
                + "{\"cmd\":\"aimPtz\",\"pan\":-12.5,\"tilt\":4.0,\"zoom\":300},"
                + "{\"cmd\":\"trackColors\",\"on\":true},"
                + "{\"cmd\":\"bindChannel\",\"channel\":3,\"color\":\"#00ff7f\"},"
                + "{\"cmd\":\"sonarCycle\",\"msPerFiring\":40},"
                + "{\"cmd\":\"motors\",\"on\":true},"
                + "{\"cmd\":\"draw\",\"layer\":\"frontier\",\"figures\":[{\"kind\":\"cells\",\"color\":\"#ff0000\","
                + "\"xy\":[0.0,0.0,500.0,500.0]}]},"
                + "{\"cmd\":\"metric\",\"name\":\"cellsExplored\",\"value\":37.5},"
                + "{\"cmd\":\"endRun\",\"reason\":\"gold found ✓\"}]}", json);
    }

    @Test
    void jsonDecodesAHandWrittenMessage() throws FrameException {
        byte[] payload = "{\"type\":\"robotRequests\",\"step\":5,\"commands\":[{\"cmd\":\"vel\",\"vel\":200}]}"
                .getBytes(StandardCharsets.UTF_8);

        assertEquals(new RobotRequests(5, List.of(new Command.SetVel(200))),
                new MessageCodec(Format.JSON).decode(payload));
    }

    @Test
    void garbagePayloadIsUndecodable() {
        byte[] garbage = {1, 2, 3, 4, 5};

        FrameException e = assertThrows(FrameException.class, () -> new MessageCodec().decode(garbage));

        assertTrue(e.getMessage().startsWith("undecodable frame of 5 bytes"), e.getMessage());
    }

    @Test
    void unknownMessageTypeIsNamed() {
        byte[] payload = "{\"type\":\"x\"}".getBytes(StandardCharsets.UTF_8);

        FrameException e = assertThrows(FrameException.class, () -> new MessageCodec(Format.JSON).decode(payload));

        assertEquals("unknown message type 'x'", e.getMessage());
    }

    @Test
    void unknownCommandTypeIsNamed() {
        byte[] payload = "{\"type\":\"robotRequests\",\"step\":5,\"commands\":[{\"cmd\":\"fly\"}]}"
                .getBytes(StandardCharsets.UTF_8);

        FrameException e = assertThrows(FrameException.class, () -> new MessageCodec(Format.JSON).decode(payload));

        assertEquals("unknown message type 'fly'", e.getMessage());
    }

    @Test
    void missingTypeIsNotReportedAsUnknownTypeNull() {
        byte[] payload = "{\"reason\":\"done\"}".getBytes(StandardCharsets.UTF_8);

        FrameException e = assertThrows(FrameException.class, () -> new MessageCodec(Format.JSON).decode(payload));

        assertTrue(e.getMessage().startsWith("no message type in frame of 17 bytes: "), e.getMessage());
    }

    @Test
    void aCommandValueThatBreaksItsRuleIsAnInvalidValueNamingTheRule() {
        byte[] payload = ("{\"type\":\"robotRequests\",\"step\":5,\"commands\":[{\"cmd\":\"vel\",\"vel\":200},"
                + "{\"cmd\":\"laser\",\"on\":true,\"increment\":0.25,\"maxRange\":8000}]}")
                .getBytes(StandardCharsets.UTF_8);

        InvalidValueException e = assertThrows(InvalidValueException.class,
                () -> new MessageCodec(Format.JSON).decode(payload));

        assertEquals("0.25 was supplied for the laser increment: a SICK LMS200 scans at 1 or 0.5 degrees",
                e.getMessage());
    }

    @Test
    void aNonFiniteVelocityOnTheWireIsAnInvalidValue() throws Exception {
        Map<String, Object> vel = new LinkedHashMap<>();
        vel.put("cmd", "vel");
        vel.put("vel", Double.NaN);
        Map<String, Object> requests = new LinkedHashMap<>();
        requests.put("type", "robotRequests");
        requests.put("step", 2);
        requests.put("commands", List.of(vel));
        byte[] payload = new SmileMapper().writeValueAsBytes(requests);

        InvalidValueException e = assertThrows(InvalidValueException.class, () -> new MessageCodec().decode(payload));

        assertEquals("NaN was supplied for vel: it must be a finite number", e.getMessage());
    }

    @Test
    void aConstructorFailureThatIsNoRuleIsUndecodable() {
        byte[] payload = "{\"type\":\"robotRequests\",\"step\":5,\"commands\":null}".getBytes(StandardCharsets.UTF_8);

        FrameException e = assertThrows(FrameException.class, () -> new MessageCodec(Format.JSON).decode(payload));

        assertFalse(e instanceof InvalidValueException, e.toString());
        assertTrue(e.getMessage().startsWith("undecodable frame of 49 bytes"), e.getMessage());
    }

    @Test
    void unknownPropertyIsRejected() {
        byte[] payload = "{\"type\":\"bye\",\"reason\":\"done\",\"extra\":1}".getBytes(StandardCharsets.UTF_8);

        FrameException e = assertThrows(FrameException.class, () -> new MessageCodec(Format.JSON).decode(payload));

        assertTrue(e.getMessage().startsWith("undecodable frame of 40 bytes: Unrecognized field \"extra\""),
                e.getMessage());
    }

    @Test
    void nullForAPrimitiveIsRejected() {
        byte[] payload = "{\"type\":\"welcome\",\"name\":\"r\",\"stepMs\":null,\"state\":null}"
                .getBytes(StandardCharsets.UTF_8);

        FrameException e = assertThrows(FrameException.class, () -> new MessageCodec(Format.JSON).decode(payload));

        assertTrue(e.getMessage().startsWith("undecodable"), e.getMessage());
    }

    @Test
    void jsonNullPayloadIsRejected() {
        byte[] payload = "null".getBytes(StandardCharsets.UTF_8);

        assertThrows(FrameException.class, () -> new MessageCodec(Format.JSON).decode(payload));
    }

    /**
     * Smile carries text as UTF-8, and Jackson's Smile parser reads the 3-byte form of a lone
     * surrogate (not UTF-8) into a string that no encoder can write again: an Environment passing it
     * on (a robot's words to the viewers, its type in a refusal) failed in its step loop.
     */
    @Test
    void textThatIsNotUtf8IsRefused() throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (JsonGenerator g = new SmileFactory().createGenerator(out)) {
            g.writeStartObject();
            g.writeStringField("type", "viewerHello");
            g.writeFieldName("name");
            g.writeUTF8String(new byte[] {'v', (byte) 0xed, (byte) 0xa0, (byte) 0x80}, 0, 4);
            g.writeEndObject();
        }

        FrameException e = assertThrows(FrameException.class, () -> new MessageCodec().decode(out.toByteArray()));

        assertTrue(e.getMessage().contains("text with a lone surrogate at character 1: text must be valid UTF-8"),
                e.getMessage());
    }

    @Test
    void aLoneSurrogateEscapedInJsonIsRefused() {
        byte[] requests = ("{\"type\":\"robotRequests\",\"step\":1,\"commands\":[{\"cmd\":\"say\","
                + "\"text\":\"a\\udc00\"}]}").getBytes(StandardCharsets.UTF_8);

        FrameException e = assertThrows(FrameException.class, () -> new MessageCodec(Format.JSON).decode(requests));

        assertTrue(e.getMessage().contains("text with a lone surrogate at character 1"), e.getMessage());
    }

    /** Jackson failed with a NullPointerException on an array whose first element is binary, not a type name. */
    @Test
    void aTypeNameThatIsBinaryIsAFrameError() {
        byte[] payload = {0x3a, 0x29, 0x0a, 0x01, (byte) 0xf8, (byte) 0xe8, (byte) 0x81, 0, 0, (byte) 0xf9};

        FrameException e = assertThrows(FrameException.class, () -> new MessageCodec().decode(payload));

        assertTrue(e.getMessage().startsWith("undecodable frame of 10 bytes: "), e.getMessage());
    }

    /** A reason goes into the Environment's log line about the peer: what the peer wrote cannot start a line of its own. */
    @Test
    void aReasonQuotingThePeerCannotForgeALogLine() {
        byte[] field = "{\"type\":\"bye\",\"reason\":\"x\",\"a\\nSEVERE: forged\":1}".getBytes(StandardCharsets.UTF_8);
        byte[] type = "{\"type\":\"x\\nSEVERE: forged\"}".getBytes(StandardCharsets.UTF_8);

        for (byte[] payload : List.of(field, type)) {
            FrameException e = assertThrows(FrameException.class, () -> new MessageCodec(Format.JSON).decode(payload));

            assertTrue(e.getMessage().chars().allMatch(c -> c >= 0x20 && c < 0x7f), e.getMessage());
            assertTrue(e.getMessage().contains("\\u000aSEVERE: forged"), e.getMessage());
        }
    }
}
