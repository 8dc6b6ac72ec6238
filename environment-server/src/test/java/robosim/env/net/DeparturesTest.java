package robosim.env.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.SocketException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.env.core.Simulation;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.Bye;
import robosim.protocol.FrameException;
import robosim.protocol.LinkHello;
import robosim.protocol.Message;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotRequests;
import robosim.protocol.Welcome;

/**
 * How the session rules mark the robots that go before the end of the run (left, dropped, lost),
 * with the step open and the reason, over real loopback connections to {@code empty-room.xml}'s r1
 * and r2.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class DeparturesTest {
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

    /** Hands what the peer sent to the rules, or its end of the stream, as the step loop does. */
    private void deliver(Peer peer) throws IOException {
        List<Message> got = loopback.receive(peer.connection);
        if (got == null) {
            rules.closed(peer.connection, SessionRules.DISCONNECTED);
            return;
        }
        for (Message m : got) {
            rules.received(peer.connection, m);
        }
    }

    private Peer robot(String name) throws IOException {
        Peer peer = loopback.connect(Connection.Kind.ROBOT);
        peer.send(hello(name));
        deliver(peer);
        assertInstanceOf(Welcome.class, peer.read());
        return peer;
    }

    @Test
    void aRobotThatSaysByeIsMarkedLeftAtTheOpenStepWithItsReason() throws IOException {
        Peer r1 = robot("r1");
        robot("r2");
        rules.openStep(3);

        r1.send(new Bye("the robot's program disconnected"));
        deliver(r1);

        assertEquals(List.of(new Departure("r1", Departure.Kind.LEFT, 3, "the robot's program disconnected")),
                rules.departures());
    }

    @Test
    void aByesReasonCannotForgeALineOfTheRunReport() throws IOException {
        Peer r1 = robot("r1");
        robot("r2");
        rules.openStep(3);

        r1.send(new Bye("done\nrobot r2: pose (0, 0, 0.0) travelled 0 mm"));
        deliver(r1);

        String reason = rules.departures().get(0).reason();
        assertTrue(!reason.contains("\n") && reason.startsWith("done\\u000a"), reason);
    }

    @Test
    void aRobotWhoseConnectionClosesWithoutAByeIsMarkedLost() throws IOException {
        Peer r1 = robot("r1");
        robot("r2");
        rules.openStep(7);

        r1.close();
        deliver(r1);

        assertEquals(List.of(new Departure("r1", Departure.Kind.LOST, 7, "the connection closed without a bye")),
                rules.departures());
        assertEquals("lost at step 7: the connection closed without a bye", rules.departures().get(0).describe());
        assertEquals(List.of(), log.warnings());
    }

    @Test
    void aRobotDroppedForBreakingARuleIsToldWhyInAByeAndMarkedDropped() throws IOException {
        Peer r1 = robot("r1");
        robot("r2");
        rules.openStep(1);

        r1.send(new RobotRequests(5, List.of()));
        deliver(r1);

        String rule = "robot r1 sent requests for step 5 while step 1 is open";
        assertEquals(new Bye(rule), r1.read());
        assertTrue(r1.closedByEnvironment());
        assertEquals(List.of(new Departure("r1", Departure.Kind.DROPPED, 1, rule)), rules.departures());
        assertEquals(List.of("closing robot r1: " + rule), log.warnings());
    }

    @Test
    void aRobotDroppedAtTheStepDeadlineIsToldWhy() throws IOException {
        Peer r1 = robot("r1");
        robot("r2");
        rules.openStep(13);

        rules.drop("r1", "it did not send its requests for step 13 within 500 ms");

        assertEquals(new Bye("it did not send its requests for step 13 within 500 ms"), r1.read());
        assertEquals(Departure.Kind.DROPPED, rules.departures().get(0).kind());
    }

    @Test
    void aFrameThatCannotBeReadDropsTheRobotAndABrokenConnectionLosesIt() throws IOException {
        Peer r1 = robot("r1");
        Peer r2 = robot("r2");
        rules.openStep(2);

        rules.failed(r1.connection, new FrameException("undecodable frame of 8 bytes"));
        rules.failed(r2.connection, new SocketException("Connection reset"));

        assertEquals(new Bye("undecodable frame of 8 bytes"), r1.read());
        assertEquals(List.of(new Departure("r1", Departure.Kind.DROPPED, 2, "undecodable frame of 8 bytes"),
                new Departure("r2", Departure.Kind.LOST, 2, "the connection failed: Connection reset")),
                rules.departures());
        assertEquals(List.of("closing robot r1: undecodable frame of 8 bytes", "closing robot r2: Connection reset"),
                log.warnings());
    }

    @Test
    void aSharedLinkThatEndsWithoutAByeLosesEveryRobotOnIt() throws IOException {
        Peer link = loopback.connect(Connection.Kind.ROBOT);
        link.send(new LinkHello("test"));
        deliver(link);
        link.send(hello("r1"));
        link.send(hello("r2"));
        deliver(link);
        if (rules.connectedRobots().size() < 2) {
            deliver(link);
        }
        rules.openStep(4);

        link.close();
        deliver(link);

        assertEquals(List.of(new Departure("r1", Departure.Kind.LOST, 4, "the connection closed without a bye"),
                new Departure("r2", Departure.Kind.LOST, 4, "the connection closed without a bye")),
                rules.departures());
    }

    @Test
    void aRobotThatGoesBeforeTheRunStartsIsNotMarked() throws IOException {
        Peer r1 = robot("r1");

        r1.close();
        deliver(r1);

        assertEquals(List.of(), rules.departures());
        assertNull(rules.connectedRobots().get("r1"), "it may connect again");
    }
}
