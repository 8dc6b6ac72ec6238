package robosim.env.net;

import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
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
import robosim.protocol.LinkHello;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotRequests;
import robosim.protocol.CapturedLog;
import robosim.protocol.ViewerHello;
import robosim.protocol.Welcome;

/**
 * Text a peer chooses (a viewer's name, a link's client, a robot's type, the reason of a bye) goes
 * into the Environment's log escaped, so that a line break in it cannot forge a line: found by the
 * hostile peers of the end-to-end fuzz test.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class PeerTextInTheLogTest {
    private static final String FORGED = "x\nSEVERE: forged";
    private static final String ESCAPED = "x\\u000aSEVERE: forged";

    private CapturedLog log;
    private Loopback loopback;
    private Simulation sim;
    private SessionRules rules;

    @BeforeEach
    void open() throws IOException {
        log = new CapturedLog("robosim.env.net");
        loopback = new Loopback();
        Path root = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (!Files.isDirectory(root.resolve("testLoadFiles"))) {
            root = root.getParent();
        }
        sim = new Simulation(WorldReader.read(root.resolve("testLoadFiles/environment/empty-room.xml")));
        rules = new SessionRules(sim);
    }

    @AfterEach
    void close() throws IOException {
        log.close();
        loopback.close();
    }

    private Peer send(Connection.Kind kind, Object... messages) throws IOException {
        Peer peer = loopback.connect(kind);
        for (Object m : messages) {
            peer.send((robosim.protocol.Message) m);
            for (robosim.protocol.Message got : loopback.receive(peer.connection)) {
                rules.received(peer.connection, got);
            }
        }
        return peer;
    }

    private void loggedOneLineEach(String expected) {
        List<String> lines = log.lines();
        assertTrue(lines.stream().anyMatch(l -> l.contains(expected)), "expected '" + expected + "' in " + lines);
        assertTrue(lines.stream().noneMatch(l -> l.contains("\n") || l.contains("\r")), lines.toString());
    }

    @Test
    void aViewersNameCannotForgeALogLine() throws IOException {
        send(Connection.Kind.VIEWER, new ViewerHello(FORGED), new RobotRequests(1, List.of()));

        loggedOneLineEach("closing viewer " + ESCAPED + ": sent RobotRequests");
    }

    @Test
    void aLinksClientCannotForgeALogLine() throws IOException {
        send(Connection.Kind.ROBOT, new LinkHello(FORGED), new ViewerHello("v"));

        loggedOneLineEach("closing link of " + ESCAPED + " at ");
    }

    @Test
    void aRobotsTypeCannotForgeALogLine() throws IOException {
        send(Connection.Kind.ROBOT, new RobotHello("r1", FORGED, sim.world().robots().get(0).parameters()));

        loggedOneLineEach("refusing robot r1: robot r1 is a pioneer in the world, not a " + ESCAPED);
    }

    @Test
    void theReasonOfAByeCannotForgeALogLine() throws IOException {
        Peer robot = send(Connection.Kind.ROBOT, new RobotHello("r1", "pioneer", sim.world().robots().get(0).parameters()));
        assertInstanceOf(Welcome.class, robot.read());
        robot.send(new Bye(FORGED));
        for (robosim.protocol.Message got : loopback.receive(robot.connection)) {
            rules.received(robot.connection, got);
        }

        loggedOneLineEach("robot r1 left at step 0: " + ESCAPED);
    }
}
