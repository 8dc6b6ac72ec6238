package robosim.env.net;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.dataformat.smile.databind.SmileMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.env.core.Simulation;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.Bye;
import robosim.protocol.Command;
import robosim.protocol.CommsUpdate;
import robosim.protocol.Figure;
import robosim.protocol.ControlHello;
import robosim.protocol.ControlRequest;
import robosim.protocol.InvalidValueException;
import robosim.protocol.LinkHello;
import robosim.protocol.LinkRequests;
import robosim.protocol.Message;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotParameters;
import robosim.protocol.RobotRequests;
import robosim.protocol.Snapshot;
import robosim.protocol.SonarUnit;
import robosim.protocol.ViewerHello;
import robosim.protocol.Welcome;
import robosim.protocol.WorldDescription;

/**
 * The protocol's rules for each peer, over real loopback connections: the world is
 * {@code empty-room.xml}, two Pioneers r1 and r2; on connections of their own and on a shared link.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class SessionRulesTest {
    private Loopback loopback;
    private LogLines log;
    private Simulation sim;
    private SessionRules rules;

    @BeforeEach
    void open() throws IOException {
        loopback = new Loopback();
        log = new LogLines();
        sim = new Simulation(WorldReader.read(root().resolve("testLoadFiles/environment/empty-room.xml")));
        rules = new SessionRules(sim);
    }

    @AfterEach
    void close() throws IOException {
        log.close();
        loopback.close();
    }

    private static Path root() {
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (p != null && !Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        if (p == null) {
            throw new IllegalStateException("cannot find testLoadFiles above " + Path.of("").toAbsolutePath());
        }
        return p;
    }

    private RobotHello hello(String name, String type) {
        return new RobotHello(name, type, sim.world().robots().get(0).parameters());
    }

    /** Hands what the peer sent to the rules, as the step loop does. */
    private void deliver(Peer peer) throws IOException {
        for (Message m : loopback.receive(peer.connection)) {
            rules.received(peer.connection, m);
        }
    }

    /** A robot that has said hello and been welcomed. */
    private Peer robot(String name) throws IOException {
        Peer peer = loopback.connect(Connection.Kind.ROBOT);
        peer.send(hello(name, "pioneer"));
        deliver(peer);
        assertInstanceOf(Welcome.class, peer.read());
        return peer;
    }

    private String onlyWarning() {
        List<String> warnings = log.warnings();
        assertEquals(1, warnings.size(), warnings.toString());
        return warnings.get(0);
    }

    @Test
    void aHelloWithAWorldRobotsNameIsWelcomed() throws IOException {
        Peer peer = loopback.connect(Connection.Kind.ROBOT);

        peer.send(hello("r1", "pioneer"));
        deliver(peer);

        Welcome welcome = assertInstanceOf(Welcome.class, peer.read());
        assertEquals("r1", welcome.name());
        assertEquals(100, welcome.stepMs());
        assertEquals(1500, welcome.state().x());
        assertEquals(Set.of("r1"), rules.connectedRobots().keySet());
        assertEquals(List.of("r2"), rules.missing());
    }

    @Test
    void everyRobotOfTheWorldConnected() throws IOException {
        robot("r1");
        robot("r2");

        assertTrue(rules.allConnected());
    }

    private void assertRefused(Peer peer, String reason) throws IOException {
        Bye bye = assertInstanceOf(Bye.class, peer.read());
        assertEquals("refused: " + reason, bye.reason());
        assertTrue(peer.closedByEnvironment());
    }

    @Test
    void anUnknownNameIsRefusedNamingTheWorld() throws IOException {
        Peer peer = loopback.connect(Connection.Kind.ROBOT);

        peer.send(hello("r9", "pioneer"));
        deliver(peer);

        assertRefused(peer, "world empty-room has no robot named 'r9'");
        assertEquals(Set.of(), rules.connectedRobots().keySet());
    }

    @Test
    void aNameOutsideTheNameRuleIsRefusedAndCannotForgeALogLine() throws IOException {
        Peer peer = loopback.connect(Connection.Kind.ROBOT);

        peer.send(hello("r1\nSEVERE: forged", "pioneer"));
        deliver(peer);

        assertRefused(peer, "a robot's name is 1 to 64 letters (A-Z, a-z), digits, '_', '-' or '.'; 'r1\\u000aSEVERE:"
                + " forged' is not");
        assertTrue(onlyWarning().startsWith("refusing robot r1\\u000aSEVERE: forged: "), onlyWarning());
        assertTrue(log.warnings().stream().noneMatch(w -> w.contains("\n")), log.warnings().toString());
    }

    @Test
    void aRobotOfAnotherTypeIsRefusedNamingBoth() throws IOException {
        Peer peer = loopback.connect(Connection.Kind.ROBOT);

        peer.send(hello("r1", "scout"));
        deliver(peer);

        assertRefused(peer, "robot r1 is a pioneer in the world, not a scout");
    }

    @Test
    void aSecondProgramWithTheSameNameIsRefused() throws IOException {
        robot("r1");
        Peer second = loopback.connect(Connection.Kind.ROBOT);

        second.send(hello("r1", "pioneer"));
        deliver(second);

        assertRefused(second, "robot r1 is already connected");
        assertEquals(Set.of("r1"), rules.connectedRobots().keySet());
    }

    /** The world's p3dx with other speed limits and sonars. */
    private RobotParameters p3dx(double maxVelocity, double maxRVelocity, List<SonarUnit> sonars) {
        RobotParameters p = sim.world().robots().get(0).parameters();
        return new RobotParameters(p.robotClass(), p.subclass(), p.robotRadius(), p.robotWidth(), p.robotLengthFront(),
                p.robotLengthRear(), maxVelocity, maxRVelocity, p.transAccel(), p.transDecel(), p.rotAccel(),
                p.rotDecel(), p.diffConvFactor(), p.sonarMaxRange(), sonars, p.laserX(), p.laserY(), p.laserTh(),
                p.laserMaxRange(), p.shape());
    }

    @Test
    void aHelloWhoseParametersBreakAPhysicalBoundIsRefusedNamingTheFieldAndValue() throws Exception {
        List<SonarUnit> sonars = sim.world().robots().get(0).parameters().sonarUnits();
        List<SonarUnit> tooMany = new java.util.ArrayList<>();
        for (int i = 0; i < 80_000; i++) {
            tooMany.add(new SonarUnit(i, 0, 0, 0));
        }
        Map<RobotParameters, String> cases = new LinkedHashMap<>();
        cases.put(p3dx(Double.NaN, 300, sonars), "NaN was supplied for maxVelocity: it must be a finite number above 0"
                + " to 10000.0 mm/s");
        cases.put(p3dx(1e300, 300, sonars), "1.0E300 was supplied for maxVelocity");
        cases.put(p3dx(2200, 1e12, sonars), "1.0E12 was supplied for maxRVelocity: it must be a finite number above 0"
                + " to 3600.0 degrees/s");
        cases.put(p3dx(2200, 300, tooMany), "80000 sonars were supplied: a robot has at most 64");
        for (Map.Entry<RobotParameters, String> c : cases.entrySet()) {
            Peer peer = loopback.connect(Connection.Kind.ROBOT);

            peer.send(new RobotHello("r1", "pioneer", c.getKey()));
            deliver(peer);

            Bye bye = assertInstanceOf(Bye.class, peer.read());
            assertTrue(bye.reason().startsWith("refused: robot r1's parameters break a bound: " + c.getValue()),
                    bye.reason());
            assertTrue(peer.closedByEnvironment());
        }
        assertEquals(Set.of(), rules.connectedRobots().keySet());
        // the first refusal is logged whole, the others within its second counted in one line (on a
        // busy machine the refusals may span more seconds: a whole line or a count for each)
        assertTrue(log.warnings().get(0).startsWith("refusing robot r1: robot r1's parameters break a bound: NaN"),
                log.warnings().get(0));
        log.awaitAccounted("refusing robot r1: ", "refused robot hellos", cases.size());
    }

    @Test
    void aHelloOfAnUnknownNameAfterTheRunStartedIsStillRefused() throws IOException {
        robot("r1");
        rules.openStep(1);
        Peer late = loopback.connect(Connection.Kind.ROBOT);

        late.send(hello("r9", "pioneer"));
        deliver(late);

        assertRefused(late, "world empty-room has no robot named 'r9'");
    }

    @Test
    void aRobotWhoseFirstMessageIsNoHelloIsClosed() throws IOException {
        Peer peer = loopback.connect(Connection.Kind.ROBOT);

        peer.send(new RobotRequests(1, List.of()));
        deliver(peer);

        assertTrue(peer.closedByEnvironment());
        assertTrue(onlyWarning().endsWith(": expected robotHello or linkHello as its first message, got RobotRequests"),
                onlyWarning());
    }

    @Test
    void theRequestsForTheOpenStepAreReturnedWhenItCloses() throws IOException {
        Peer r1 = robot("r1");
        Peer r2 = robot("r2");
        rules.openStep(1);
        assertEquals(Set.of("r1", "r2"), rules.waitingFor());

        r1.send(new RobotRequests(1, List.of(new Command.SetVel(200), new Command.SetRotVel(-10))));
        deliver(r1);
        r2.send(new RobotRequests(1, List.of()));
        deliver(r2);

        assertEquals(Set.of(), rules.waitingFor());
        assertEquals(Map.of("r1", List.of(new Command.SetVel(200), new Command.SetRotVel(-10)), "r2", List.of()),
                rules.closeStep());
    }

    @Test
    void aRobotThatSentNothingIsAbsentFromTheStepsRequests() throws IOException {
        Peer r1 = robot("r1");
        robot("r2");
        rules.openStep(1);

        r1.send(new RobotRequests(1, List.of(new Command.Stop())));
        deliver(r1);

        assertEquals(Set.of("r2"), rules.waitingFor());
        assertEquals(Map.of("r1", List.of(new Command.Stop())), rules.closeStep());
        assertEquals(Set.of(), rules.waitingFor());
    }

    @Test
    void eachStepCollectsItsOwnRequests() throws IOException {
        Peer r1 = robot("r1");
        rules.openStep(1);
        r1.send(new RobotRequests(1, List.of(new Command.SetVel(200))));
        deliver(r1);
        rules.closeStep();

        rules.openStep(2);

        assertEquals(Map.of(), rules.closeStep());
    }

    @Test
    void requestsForAStepThatIsNotOpenCloseThatRobot() throws IOException {
        Peer r1 = robot("r1");
        robot("r2");
        rules.openStep(1);

        r1.send(new RobotRequests(5, List.of()));
        deliver(r1);

        assertTrue(r1.closedByEnvironment());
        assertEquals("closing robot r1: robot r1 sent requests for step 5 while step 1 is open", onlyWarning());
        assertEquals(Set.of("r2"), rules.connectedRobots().keySet());
        assertEquals(Set.of("r2"), rules.waitingFor());
    }

    @Test
    void requestsBeforeAStepIsOpenCloseThatRobot() throws IOException {
        Peer r1 = robot("r1");

        r1.send(new RobotRequests(1, List.of()));
        deliver(r1);

        assertTrue(r1.closedByEnvironment());
        assertEquals("closing robot r1: robot r1 sent requests for step 1 before step 1 was opened", onlyWarning());
    }

    @Test
    void requestsSentTwiceForAStepCloseThatRobot() throws IOException {
        Peer r1 = robot("r1");
        robot("r2");
        rules.openStep(1);
        r1.send(new RobotRequests(1, List.of()));
        deliver(r1);

        r1.send(new RobotRequests(1, List.of()));
        deliver(r1);

        assertTrue(r1.closedByEnvironment());
        assertEquals("closing robot r1: robot r1 sent requests for step 1 after it had already sent its requests"
                + " for step 1", onlyWarning());
        assertEquals(Set.of("r2"), rules.connectedRobots().keySet());
    }

    private static byte[] requestsWith(long step, Map<String, Object> command) throws IOException {
        Map<String, Object> requests = new LinkedHashMap<>();
        requests.put("type", "robotRequests");
        requests.put("step", step);
        requests.put("commands", List.of(command));
        return new SmileMapper().writeValueAsBytes(requests);
    }

    @Test
    void aValueThatBreaksACommandsRuleClosesThatRobotNamingTheStep() throws IOException {
        Peer r1 = robot("r1");
        robot("r2");
        rules.openStep(1);

        r1.sendFrame(requestsWith(1, Map.of("cmd", "vel", "vel", Double.NaN)));
        InvalidValueException e = assertThrows(InvalidValueException.class, () -> loopback.receive(r1.connection));
        rules.invalid(r1.connection, e.getMessage());

        assertTrue(r1.closedByEnvironment());
        assertEquals("closing robot r1: robot r1 sent an invalid request for step 1: NaN was supplied for vel:"
                + " it must be a finite number", onlyWarning());
        assertEquals(Set.of("r2"), rules.connectedRobots().keySet());
        assertEquals(Set.of("r2"), rules.waitingFor());
    }

    @Test
    void aValueThatBreaksARuleBeforeAStepIsOpenNamesTheNextStep() throws IOException {
        Peer r1 = robot("r1");

        r1.sendFrame(requestsWith(1, Map.of("cmd", "laser", "on", true, "increment", 0.25, "maxRange", 8000.0)));
        InvalidValueException e = assertThrows(InvalidValueException.class, () -> loopback.receive(r1.connection));
        rules.invalid(r1.connection, e.getMessage());

        assertTrue(r1.closedByEnvironment());
        assertEquals("closing robot r1: robot r1 sent an invalid request before step 1 was opened: 0.25 was"
                + " supplied for the laser increment: a SICK LMS200 scans at 1 or 0.5 degrees", onlyWarning());
    }

    @Test
    void aViewersHelloIsAnsweredWithTheWorldAndTheCurrentState() throws IOException {
        sim.step(Map.of("r1", List.of(new Command.SetVel(300))));
        Peer viewer = loopback.connect(Connection.Kind.VIEWER);

        viewer.send(new ViewerHello("v"));
        deliver(viewer);

        WorldDescription world = assertInstanceOf(WorldDescription.class, viewer.read());
        assertEquals("empty-room", world.name());
        assertArrayEquals(loopback.codec.encode(sim.snapshot()), loopback.codec.encode(viewer.read()));
        assertEquals(1, rules.viewerCount());
    }

    @Test
    void aViewerThatAttachesMidRunGetsEveryDrawingInItsFirstSnapshot() throws IOException {
        Figure cell = new Figure(Figure.CELLS, "", new double[] {0, 0, 500, 500});
        sim.step(Map.of("r1", List.of(new Command.Draw("map", List.of(cell)))));
        sim.step(Map.of("r2", List.of(new Command.Draw("frontier", List.of(cell)))));
        Peer viewer = loopback.connect(Connection.Kind.VIEWER);

        viewer.send(new ViewerHello("v"));
        deliver(viewer);

        assertInstanceOf(WorldDescription.class, viewer.read());
        Snapshot first = assertInstanceOf(Snapshot.class, viewer.read());
        assertEquals(List.of(new Snapshot.Drawing("r1", "map", List.of(cell)),
                new Snapshot.Drawing("r2", "frontier", List.of(cell))), first.drawings());
    }

    @Test
    void aViewerThatSendsAnythingAfterItsHelloIsClosed() throws IOException {
        Peer viewer = loopback.connect(Connection.Kind.VIEWER);
        viewer.send(new ViewerHello("v"));
        deliver(viewer);

        viewer.send(new RobotRequests(1, List.of()));
        deliver(viewer);

        assertTrue(viewer.closedByEnvironment());
        assertEquals("closing viewer v: sent RobotRequests; a viewer sends viewerHello once and then nothing",
                onlyWarning());
    }

    @Test
    void aViewerThatSaysHelloTwiceIsClosedAndCountedOnceEvenWithoutAName() throws IOException {
        Peer viewer = loopback.connect(Connection.Kind.VIEWER);
        viewer.send(new ViewerHello(null));
        deliver(viewer);

        viewer.send(new ViewerHello(null));
        deliver(viewer);

        assertTrue(viewer.closedByEnvironment());
        assertEquals(1, rules.viewerCount());
        assertEquals("closing viewer (unnamed): sent ViewerHello; a viewer sends viewerHello once and then nothing",
                onlyWarning());
    }

    @Test
    void aViewerWhoseFirstMessageIsNoHelloIsClosed() throws IOException {
        Peer viewer = loopback.connect(Connection.Kind.VIEWER);

        viewer.send(hello("r1", "pioneer"));
        deliver(viewer);

        assertTrue(viewer.closedByEnvironment());
        assertTrue(onlyWarning().endsWith(": sent RobotHello; the viewer port's first message is viewerHello or"
                + " controlHello"),
                onlyWarning());
        assertEquals(Set.of(), rules.connectedRobots().keySet());
    }

    /**
     * A shared link, a connection carrying many robots: each robot on it is held to the rules a robot
     * of its own connection is, and one that breaks them is dropped alone.
     */
    @Nested
    class SharedLinks {
        /** A link on which {@code robots} have said hello and been welcomed, in order. */
        private Peer link(String... robots) throws IOException {
            Peer link = loopback.connect(Connection.Kind.ROBOT);
            link.send(new LinkHello("test"));
            deliver(link);
            for (String r : robots) {
                link.send(hello(r, "pioneer"));
                deliver(link);
            }
            for (String r : robots) {
                assertEquals(r, assertInstanceOf(Welcome.class, link.read()).name());
            }
            return link;
        }

        @Test
        void oneLinkCarriesEveryRobotThatSaysHelloOnIt() throws IOException {
            Peer link = link("r1", "r2");

            assertTrue(rules.allConnected());
            assertSame(rules.connectedRobots().get("r1"), rules.connectedRobots().get("r2"));
            assertTrue(link.connection.isLink());
            assertEquals(List.of("r1", "r2"), link.connection.robots());
        }

        @Test
        void aRobotRefusedOnALinkIsToldByNameAndTheLinkGoesOn() throws IOException {
            Peer link = link();

            link.send(hello("r9", "pioneer"));
            deliver(link);
            link.send(hello("r1", "pioneer"));
            deliver(link);

            assertEquals(new Bye("refused: world empty-room has no robot named 'r9'", "r9"), link.read());
            assertEquals("r1", assertInstanceOf(Welcome.class, link.read()).name());
            assertEquals(Set.of("r1"), rules.connectedRobots().keySet());
        }

        @Test
        void eachRobotsRequestsAreCollectedWhetherTheyComeInOneFrameOrInParts() throws IOException {
            Peer link = link("r1", "r2");
            rules.openStep(1);

            link.send(new LinkRequests(1, List.of(new LinkRequests.ForRobot("r2", List.of()))));
            deliver(link);
            assertEquals(Set.of("r1"), rules.waitingFor());
            link.send(new LinkRequests(1, List.of(new LinkRequests.ForRobot("r1", List.of(new Command.SetVel(200))))));
            deliver(link);

            assertEquals(Set.of(), rules.waitingFor());
            assertEquals(Map.of("r1", List.of(new Command.SetVel(200)), "r2", List.of()), rules.closeStep());
        }

        @Test
        void aRobotThatBreaksARuleOnALinkIsDroppedAloneAndToldWhy() throws IOException {
            Peer link = link("r1", "r2");
            rules.openStep(1);

            link.send(new LinkRequests(1, List.of(new LinkRequests.ForRobot("r2", List.of()))));
            deliver(link);
            link.send(new LinkRequests(1, List.of(new LinkRequests.ForRobot("r2", List.of()),
                    new LinkRequests.ForRobot("r1", List.of()))));
            deliver(link);

            String rule = "robot r2 sent requests for step 1 after it had already sent its requests for step 1";
            assertEquals(List.of("closing robot r2: " + rule), log.warnings());
            assertEquals(new Bye(rule, "r2"), link.read());
            assertEquals(Set.of("r1"), rules.connectedRobots().keySet());
            assertEquals(Map.of("r1", List.of(), "r2", List.of()), rules.closeStep(),
                    "r2's requests for step 1 came in time; it is dropped from here on");
        }

        @Test
        void aLinkCannotAnswerForARobotItDoesNotCarry() throws IOException {
            Peer link = link("r1");
            Peer r2 = loopback.connect(Connection.Kind.ROBOT);
            r2.send(hello("r2", "pioneer"));
            deliver(r2);
            assertInstanceOf(Welcome.class, r2.read());
            rules.openStep(1);

            link.send(new LinkRequests(1, List.of(new LinkRequests.ForRobot("r2", List.of(new Command.Stop())),
                    new LinkRequests.ForRobot("r1", List.of()))));
            deliver(link);

            assertEquals(Set.of("r2"), rules.waitingFor());
            assertEquals(Map.of("r1", List.of()), rules.closeStep());
        }

        @Test
        void aByeNamingOneRobotTakesItOutAndTheOthersStay() throws IOException {
            Peer link = link("r1", "r2");

            link.send(new Bye("its program ended", "r1"));
            deliver(link);

            assertEquals(new Bye("goodbye", "r1"), link.read());
            assertEquals(Set.of("r2"), rules.connectedRobots().keySet());
            assertEquals(List.of(), log.warnings());
        }

        @Test
        void aByeForTheWholeLinkOrItsEndTakesOutEveryRobotOnIt() throws IOException {
            Peer link = link("r1", "r2");

            link.send(new Bye("the program ended"));
            deliver(link);

            assertEquals(Set.of(), rules.connectedRobots().keySet());
            assertTrue(link.closedByEnvironment());
        }

        @Test
        void aFrameThatCannotBeReadClosesTheLinkNamingEachRobot() throws IOException {
            Peer link = link("r1", "r2");
            rules.openStep(1);
            Map<String, Object> requests = new LinkedHashMap<>();
            requests.put("type", "linkRequests");
            requests.put("step", 1);
            requests.put("robots", List.of(Map.of("robot", "r1", "commands", List.of(Map.of("cmd", "vel", "vel",
                    Double.NaN)))));

            link.sendFrame(new SmileMapper().writeValueAsBytes(requests));
            InvalidValueException e = assertThrows(InvalidValueException.class, () -> loopback.receive(link.connection));
            rules.invalid(link.connection, e.getMessage());

            assertEquals(Set.of(), rules.connectedRobots().keySet());
            assertTrue(link.closedByEnvironment());
            List<String> warnings = log.warnings();
            assertEquals(3, warnings.size(), warnings.toString());
            assertTrue(warnings.get(0).startsWith("closing robot r1: its link sent an invalid message: NaN was supplied"),
                    warnings.get(0));
            assertTrue(warnings.get(1).startsWith("closing robot r2: its link sent an invalid message"), warnings.get(1));
            assertTrue(warnings.get(2).startsWith("closing link of test at "), warnings.get(2));
        }

        @Test
        void aLinkThatSendsWhatNoLinkSendsIsClosed() throws IOException {
            Peer link = link("r1");

            link.send(new RobotRequests(1, List.of()));
            deliver(link);

            assertTrue(link.closedByEnvironment());
            assertNull(rules.connectedRobots().get("r1"));
        }
    }

    /**
     * A run with a secret: every hello must present it (a viewer's too, unless anyone may watch), and
     * only a control client may change the run.
     */
    @Nested
    class WithASecret {
        private static final String SECRET = "s3cret-s3cret-s3cret-s3cret";

        private void guard(boolean publicView) {
            rules = new SessionRules(sim, new Access(SECRET, publicView), Limits.defaults());
        }

        private RobotHello hello(String name, String token) {
            return new RobotHello(name, "pioneer", sim.world().robots().get(0).parameters(), token);
        }

        @Test
        void aRobotThatPresentsTheSecretIsWelcomed() throws IOException {
            guard(false);
            Peer peer = loopback.connect(Connection.Kind.ROBOT);

            peer.send(hello("r1", SECRET));
            deliver(peer);

            assertEquals("r1", assertInstanceOf(Welcome.class, peer.read()).name());
        }

        @Test
        void aRobotWithoutTheSecretIsRefusedAndCannotSquatTheName() throws IOException {
            guard(false);
            Peer squatter = loopback.connect(Connection.Kind.ROBOT);
            squatter.send(hello("r1", null));
            deliver(squatter);
            Peer guesser = loopback.connect(Connection.Kind.ROBOT);
            guesser.send(hello("r1", "not-the-secret-at-all"));
            deliver(guesser);

            assertRefused(squatter, "robot r1 presented no run secret; this Environment admits only those who"
                    + " present the secret it printed at its start (a --token option, the ROBOSIM_TOKEN variable, or"
                    + " the file it wrote)");
            Bye bye = assertInstanceOf(Bye.class, guesser.read());
            assertTrue(bye.reason().startsWith("refused: robot r1 presented a wrong run secret;"), bye.reason());
            assertEquals(Set.of(), rules.connectedRobots().keySet());
            // the real program still gets its name, and then a second claim with the secret is refused
            Peer real = loopback.connect(Connection.Kind.ROBOT);
            real.send(hello("r1", SECRET));
            deliver(real);
            assertEquals("r1", assertInstanceOf(Welcome.class, real.read()).name());
            Peer second = loopback.connect(Connection.Kind.ROBOT);
            second.send(hello("r1", SECRET));
            deliver(second);
            assertRefused(second, "robot r1 is already connected");
            assertTrue(log.warnings().stream().noneMatch(w -> w.contains(SECRET)), log.warnings().toString());
        }

        @Test
        void aSharedLinkWithoutTheSecretIsRefusedBeforeAnyRobot() throws IOException {
            guard(false);
            Peer link = loopback.connect(Connection.Kind.ROBOT);

            link.send(new LinkHello("intruder"));
            deliver(link);

            Bye bye = assertInstanceOf(Bye.class, link.read());
            assertTrue(bye.reason().startsWith("refused: a shared link presented no run secret"), bye.reason());
            assertTrue(link.closedByEnvironment());
        }

        @Test
        void aSharedLinkWithTheSecretCarriesRobotsThatDoNotRepeatIt() throws IOException {
            guard(false);
            Peer link = loopback.connect(Connection.Kind.ROBOT);

            link.send(new LinkHello("team", SECRET));
            deliver(link);
            link.send(hello("r1", null));
            deliver(link);

            assertEquals("r1", assertInstanceOf(Welcome.class, link.read()).name());
        }

        @Test
        void aViewerNeedsTheSecretUnlessTheViewIsPublic() throws IOException {
            guard(false);
            Peer stranger = loopback.connect(Connection.Kind.VIEWER);
            stranger.send(new ViewerHello("peeker"));
            deliver(stranger);
            Peer friend = loopback.connect(Connection.Kind.VIEWER);
            friend.send(new ViewerHello("friend", SECRET));
            deliver(friend);

            Bye bye = assertInstanceOf(Bye.class, stranger.read());
            assertTrue(bye.reason().startsWith("refused: viewer peeker presented no run secret"), bye.reason());
            assertInstanceOf(WorldDescription.class, friend.read());

            guard(true);
            Peer anyone = loopback.connect(Connection.Kind.VIEWER);
            anyone.send(new ViewerHello("anyone"));
            deliver(anyone);
            assertInstanceOf(WorldDescription.class, anyone.read());
        }

        @Test
        void aViewerCannotChangeTheCommsSettingsEvenWithTheSecret() throws IOException {
            guard(true);
            Peer viewer = loopback.connect(Connection.Kind.VIEWER);
            viewer.send(new ViewerHello("v", SECRET));
            deliver(viewer);
            viewer.read();
            viewer.read();

            viewer.send(new CommsUpdate(null, null, null, 1.0, null));
            deliver(viewer);

            Bye bye = assertInstanceOf(Bye.class, viewer.read());
            assertTrue(bye.reason().startsWith("refused: a viewer cannot change the run"), bye.reason());
            assertEquals(0.0, sim.commsSettings().lossProbability());
        }

        @Test
        void aViewerCannotControlTheRun() throws IOException {
            guard(true);
            RunControl control = new RunControl(rules.run(), rules, Limits.defaults().maxRobots(), rules.limited());
            rules.routeControlTo(control);
            Peer viewer = loopback.connect(Connection.Kind.VIEWER);
            viewer.send(new ViewerHello("v", SECRET));
            deliver(viewer);
            viewer.read();
            viewer.read();

            viewer.send(new ControlRequest(1, "stop", List.of()));
            deliver(viewer);

            Bye bye = assertInstanceOf(Bye.class, viewer.read());
            assertTrue(bye.reason().startsWith("refused: a viewer cannot change the run"), bye.reason());
            assertEquals(null, control.atBoundary(), "nothing was queued to stop the run");
        }

        @Test
        void aControlClientChangesTheCommsSettingsOnlyWithTheSecret() throws IOException {
            guard(true);
            Peer stranger = loopback.connect(Connection.Kind.VIEWER);
            stranger.send(new ControlHello("comms", null));
            deliver(stranger);
            Peer control = loopback.connect(Connection.Kind.VIEWER);
            control.send(new ControlHello("comms", SECRET));
            deliver(control);

            control.send(new CommsUpdate(null, null, 3, null, null));
            deliver(control);

            Bye bye = assertInstanceOf(Bye.class, stranger.read());
            assertTrue(bye.reason().startsWith("refused: control client comms presented no run secret"), bye.reason());
            assertEquals(3, assertInstanceOf(CommsUpdate.class, control.read()).latencySteps());
            assertEquals(3, sim.commsSettings().latencySteps());
        }

        @Test
        void viewersBeyondTheCapAreRefusedNamingIt() throws IOException {
            rules = new SessionRules(sim, Access.secret(SECRET), Limits.defaults().withMaxViewers(1));
            Peer first = loopback.connect(Connection.Kind.VIEWER);
            first.send(new ViewerHello("first", SECRET));
            deliver(first);
            Peer second = loopback.connect(Connection.Kind.VIEWER);
            second.send(new ViewerHello("second", SECRET));
            deliver(second);

            assertInstanceOf(WorldDescription.class, first.read());
            assertEquals("refused: 1 viewers are attached, the most this Environment allows (--max-viewers)",
                    assertInstanceOf(Bye.class, second.read()).reason());
            assertEquals(1, rules.viewerCount());
        }
    }

    /** Viewers that do not read hold queues; together they stay within one budget. */
    @Nested
    class ViewerBudget {
        private static final long BUDGET = 4L << 20;

        /** A snapshot of about 1 MB: one robot with a long laser scan. */
        private robosim.protocol.Snapshot big(long step) {
            int[] scan = new int[300_000];
            java.util.Arrays.fill(scan, 7_654_321);
            return new robosim.protocol.Snapshot(step, step * 100, List.of(new robosim.protocol.Snapshot.RobotView(
                    "r1", 0, 0, 0, false, true, new int[0], 0, 0, 0, scan, 1)));
        }

        private Peer viewer(String name) throws IOException {
            Peer v = loopback.connect(Connection.Kind.VIEWER, BUDGET, 4096);
            v.send(new ViewerHello(name));
            deliver(v);
            return v;
        }

        @Test
        void theViewerFurthestBehindIsDroppedFirstAndNamed() throws IOException {
            rules = new SessionRules(sim, Access.open(), Limits.defaults().withViewerBudget(BUDGET));
            Peer early = viewer("early");
            rules.broadcastSnapshot(big(1), loopback.codec);
            rules.broadcastSnapshot(big(2), loopback.codec);
            Peer late = viewer("late");

            for (int step = 3; step <= 6 && rules.viewerCount() == 2; step++) {
                rules.broadcastSnapshot(big(step), loopback.codec);
            }

            assertEquals(1, rules.viewerCount());
            assertTrue(early.connection.isClosed());
            assertTrue(!late.connection.isClosed());
            assertTrue(late.connection.queuedBytes() <= BUDGET);
            String warning = onlyWarning();
            assertTrue(warning.startsWith("closing viewer early: it is the viewer furthest behind ("), warning);
            assertTrue(warning.endsWith(", over the budget of 4194304 (--viewer-budget)"), warning);
        }
    }
}
