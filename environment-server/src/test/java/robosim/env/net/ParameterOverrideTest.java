package robosim.env.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.env.core.Simulation;
import robosim.env.world.xml.WorldReader;
import robosim.params.ParameterFileReader;
import robosim.protocol.Message;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotParameters;
import robosim.protocol.Welcome;

/**
 * A robot program whose parameters differ from its world file's is told of in one line naming the
 * robot, the first field that differs with both values, and which file wins (the program's).
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class ParameterOverrideTest {
    private final Logger logger = Logger.getLogger(SessionRules.class.getName());
    private final List<String> lines = new ArrayList<>();
    private final Handler handler = new Handler() {
        @Override
        public synchronized void publish(LogRecord r) {
            if (r.getLevel().intValue() >= Level.INFO.intValue() && r.getMessage().contains("parameters differ")) {
                lines.add(r.getMessage());
            }
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
        }
    };
    private Loopback loopback;
    private Simulation sim;
    private SessionRules rules;

    @BeforeEach
    void open() throws IOException {
        logger.addHandler(handler);
        loopback = new Loopback();
        sim = new Simulation(WorldReader.read(root().resolve("testLoadFiles/environment/empty-room.xml")));
        rules = new SessionRules(sim);
    }

    @AfterEach
    void close() throws IOException {
        logger.removeHandler(handler);
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

    private void hello(RobotParameters params) throws IOException {
        Peer peer = loopback.connect(Connection.Kind.ROBOT);
        peer.send(new RobotHello("r1", "pioneer", params));
        for (Message m : loopback.receive(peer.connection)) {
            rules.received(peer.connection, m);
        }
        assertInstanceOf(Welcome.class, peer.read());
    }

    @Test
    void aProgramWithOtherParametersIsNamedInOneLineAndWins() throws IOException {
        RobotParameters p3dxSh = ParameterFileReader.read(root().resolve("testLoadFiles/robots/p3dx-sh.p"));

        hello(p3dxSh);

        assertEquals(List.of("robot r1: its program's parameters differ from the world's file p3dx.p (first: "
                + "subclass p3dx in the world's file, p3dx-sh in the program's); the program's parameters win"), lines);
    }

    @Test
    void aProgramWithTheWorldsParametersIsNotMentioned() throws IOException {
        hello(sim.world().robots().get(0).parameters());

        assertEquals(List.of(), lines);
    }

    @Test
    void theFirstDifferingFieldIsNamedWithBothValues() {
        RobotParameters world = sim.world().robots().get(0).parameters();
        RobotParameters slower = new RobotParameters(world.robotClass(), world.subclass(), world.robotRadius(),
                world.robotWidth(), world.robotLengthFront(), world.robotLengthRear(), 1500, world.maxRVelocity(),
                world.transAccel(), world.transDecel(), world.rotAccel(), world.rotDecel(), world.diffConvFactor(),
                world.sonarMaxRange(), world.sonarUnits(), world.laserX(), world.laserY(), world.laserTh(),
                world.laserMaxRange(), world.shape());

        assertEquals("maxVelocity 2200.0 in the world's file, 1500.0 in the program's",
                ParameterDifference.first(world, slower));
        assertNull(ParameterDifference.first(world, world));
    }
}
