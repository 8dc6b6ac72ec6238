package robosim.env.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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
import org.junit.jupiter.api.io.TempDir;
import robosim.env.core.Simulation;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.Bye;
import robosim.protocol.Message;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotParameters;
import robosim.protocol.Snapshot;
import robosim.protocol.Welcome;

/**
 * Robots an open world does not name, over real loopback connections: placed at the first free
 * {@code <spawn>} pose, refused with the reason when none is free or they are of another type.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class OpenWorldTest {
    @TempDir
    Path dir;
    private Loopback loopback;
    private LogLines log;
    private Simulation sim;
    private SessionRules rules;
    private RobotParameters p3dx;

    @BeforeEach
    void open() throws IOException {
        loopback = new Loopback();
        log = new LogLines();
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (!Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        p3dx = WorldReader.read(p.resolve("testLoadFiles/environment/empty-room.xml")).robots().get(0).parameters();
    }

    @AfterEach
    void close() throws IOException {
        log.close();
        loopback.close();
    }

    /** An open 6 m room with two spawn poses, the second 3 m to the right of the first. */
    private void world(String spawns, Limits limits) throws IOException {
        Path file = dir.resolve("arena.xml");
        Files.writeString(file, """
                <world name="arena" width="6000" height="6000" open="true">
                  %s
                </world>
                """.formatted(spawns));
        World w = WorldReader.read(file);
        sim = new Simulation(w);
        rules = new SessionRules(sim, Access.open(), limits);
    }

    private void world() throws IOException {
        world("<spawn x=\"1500\" y=\"1500\"/>\n  <spawn x=\"4500\" y=\"1500\" th=\"90\"/>", Limits.defaults());
    }

    private Message hello(String name, String type) throws IOException {
        Peer peer = loopback.connect(Connection.Kind.ROBOT);
        peer.send(new RobotHello(name, type, p3dx));
        for (Message m : loopback.receive(peer.connection)) {
            rules.received(peer.connection, m);
        }
        return peer.read();
    }

    @Test
    void aRobotTheWorldDoesNotNameIsPlacedAtTheFirstSpawnPose() throws IOException {
        world();

        Welcome w = assertInstanceOf(Welcome.class, hello("visitor", "pioneer"));

        assertEquals(List.of(1500.0, 1500.0, 0.0), List.of(w.state().x(), w.state().y(), w.state().th()));
        assertEquals(List.of("visitor"), sim.robotNames());
        assertEquals("pioneer", sim.type("visitor"));
        assertTrue(rules.takeWorldChanged());
        assertEquals(List.of("visitor"), sim.description().robots().stream().map(r -> r.name()).toList());
    }

    @Test
    void theNextGoesToTheFirstPoseNoBodyTakes() throws IOException {
        world();
        hello("a", "pioneer");

        Welcome w = assertInstanceOf(Welcome.class, hello("b", "pioneer"));

        assertEquals(List.of(4500.0, 1500.0, 90.0), List.of(w.state().x(), w.state().y(), w.state().th()));
    }

    @Test
    void aRobotIsRefusedWhenEverySpawnPoseIsTaken() throws IOException {
        world();
        hello("a", "pioneer");
        hello("b", "pioneer");

        Bye bye = assertInstanceOf(Bye.class, hello("c", "pioneer"));

        assertTrue(bye.reason().startsWith("refused: every <spawn> pose of world arena (2) is taken or too tight for"
                + " robot c's body"), bye.reason());
        assertEquals(List.of("a", "b"), sim.robotNames());
    }

    @Test
    void anOpenWorldWithoutSpawnPosesRefusesNewcomers() throws IOException {
        world("", Limits.defaults());

        Bye bye = assertInstanceOf(Bye.class, hello("a", "pioneer"));

        assertEquals("refused: world arena has no <spawn> pose for robot a", bye.reason());
    }

    @Test
    void aNewcomerOfAnotherTypeIsRefusedNamingTheTypesAdmitted() throws IOException {
        world();

        Bye bye = assertInstanceOf(Bye.class, hello("a", "hovercraft"));

        assertEquals("refused: robot a is a hovercraft; an open world admits pioneer and scout robots", bye.reason());
    }

    @Test
    void newcomersStayWithinTheEnvironmentsRobotCap() throws IOException {
        Limits d = Limits.defaults();
        world("<spawn x=\"1500\" y=\"1500\"/>\n  <spawn x=\"4500\" y=\"1500\"/>", new Limits(d.maxPending(), 1,
                d.maxViewers(), d.maxControls(), d.helloDeadlineMs(), d.idleTimeoutMs(), d.viewerBudget()));
        hello("a", "pioneer");

        Bye bye = assertInstanceOf(Bye.class, hello("b", "pioneer"));

        assertEquals("refused: world arena has 1 robots, the most this Environment admits (--max-robots)", bye.reason());
    }

    @Test
    void anOpenWorldThatNamesNoRobotStartsAtTheFirstRobot() throws IOException {
        world();
        assertFalse(rules.allConnected());

        hello("a", "pioneer");

        assertTrue(rules.allConnected());
    }

    @Test
    void aNewcomerAfterTheStartIsRecordedAsSpawnedAndInTheNextSnapshotsEvents() throws IOException {
        world();
        hello("a", "pioneer");
        rules.start();

        hello("b", "pioneer");

        assertEquals(List.of(new Join("b", Join.Kind.SPAWNED, 1)), rules.joins());
        assertEquals(List.of(new Snapshot.Event("b", "spawned", 1, "")), rules.takeEvents());
        assertTrue(log.infos().contains("robot b (a pioneer the world does not name) placed at spawn pose (4500, 1500,"
                + " 90)"), log.infos().toString());
    }
}
