package robosim.env.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.core.Simulation;
import robosim.env.world.xml.WorldReader;
import robosim.params.ParameterFileReader;
import robosim.protocol.Message;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotParameters;
import robosim.protocol.Welcome;

/**
 * A gripper is the body's hardware: a robot the world fits with one keeps it when its program brings
 * parameters without one (an ARIA-form program brings p3dx's and asks the robot for its gripper).
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class GripperKeptTest {
    @TempDir
    Path dir;

    private final Logger logger = Logger.getLogger(SessionRules.class.getName());
    private final List<String> lines = new ArrayList<>();
    private final Handler handler = new Handler() {
        @Override
        public synchronized void publish(LogRecord r) {
            if (r.getMessage().contains("parameters differ")) {
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

    @AfterEach
    void close() throws IOException {
        logger.removeHandler(handler);
        if (loopback != null) {
            loopback.close();
        }
    }

    private static Path robots() {
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (p != null && !Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        if (p == null) {
            throw new IllegalStateException("cannot find testLoadFiles above " + Path.of("").toAbsolutePath());
        }
        return p.resolve("testLoadFiles/robots");
    }

    /** @return the parameters r1's body has after a hello with these, in a world fitting it with {@code file} */
    private RobotParameters bodyAfterHello(String file, RobotParameters program) throws IOException {
        Path world = Files.writeString(dir.resolve("w.xml"), """
                <world name="w" width="5000" height="5000" boundary="true">
                  <robot name="r1" type="pioneer" x="1000" y="1000" th="0" params="%s"/>
                </world>
                """.formatted(robots().resolve(file)));
        Simulation sim = new Simulation(WorldReader.read(world));
        SessionRules rules = new SessionRules(sim);
        logger.addHandler(handler);
        loopback = new Loopback();
        Peer peer = loopback.connect(Connection.Kind.ROBOT);
        peer.send(new RobotHello("r1", "pioneer", program));
        for (Message m : loopback.receive(peer.connection)) {
            rules.received(peer.connection, m);
        }
        assertInstanceOf(Welcome.class, peer.read());
        return sim.parameters("r1");
    }

    @Test
    void aBodyWithAGripperKeepsItWhenItsProgramBringsParametersWithout() throws IOException {
        RobotParameters p3dx = ParameterFileReader.read(robots().resolve("p3dx.p"));
        assertTrue(bodyAfterHello("p3dx-gripper.p", p3dx).hasGripper());
        assertEquals(List.of(), lines, "the same body as the world's file: nothing to say");
    }

    @Test
    void aBodyWithoutAGripperTakesItsProgramsGripperAsBefore() throws IOException {
        RobotParameters withGripper = ParameterFileReader.read(robots().resolve("p3dx-gripper.p"));
        assertTrue(bodyAfterHello("p3dx.p", withGripper).hasGripper(), "the program's parameters win");
    }
}
