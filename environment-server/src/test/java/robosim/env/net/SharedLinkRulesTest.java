package robosim.env.net;

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
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.env.core.Simulation;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.Bye;
import robosim.protocol.Command;
import robosim.protocol.InvalidValueException;
import robosim.protocol.LinkHello;
import robosim.protocol.LinkRequests;
import robosim.protocol.Message;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotRequests;
import robosim.protocol.Welcome;

/**
 * The protocol's rules for a shared link, a connection carrying many robots, over real loopback
 * connections in {@code empty-room.xml} (two Pioneers r1 and r2): each robot on it is held to the
 * rules a robot of its own connection is, and one that breaks them is dropped alone.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class SharedLinkRulesTest {
    private Loopback loopback;
    private LogLines log;
    private Simulation sim;
    private SessionRules rules;

    @BeforeEach
    void open() throws IOException {
        loopback = new Loopback();
        log = new LogLines();
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (!Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        sim = new Simulation(WorldReader.read(p.resolve("testLoadFiles/environment/empty-room.xml")));
        rules = new SessionRules(sim);
    }

    @AfterEach
    void close() throws IOException {
        log.close();
        loopback.close();
    }

    private RobotHello hello(String name) {
        return new RobotHello(name, "pioneer", sim.world().robots().get(0).parameters());
    }

    private void deliver(Peer peer) throws IOException {
        for (Message m : loopback.receive(peer.connection)) {
            rules.received(peer.connection, m);
        }
    }

    /** A link on which {@code robots} have said hello and been welcomed, in order. */
    private Peer link(String... robots) throws IOException {
        Peer link = loopback.connect(Connection.Kind.ROBOT);
        link.send(new LinkHello("test"));
        deliver(link);
        for (String r : robots) {
            link.send(hello(r));
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

        link.send(hello("r9"));
        deliver(link);
        link.send(hello("r1"));
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
        r2.send(hello("r2"));
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
