package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArGripper;
import robosim.aria.ArRobot;
import robosim.cli.Background;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.examples.gripper.GripperExample;
import robosim.protocol.Snapshot;

/** ARIA's gripperExample ({@code examples/gripper}) worked by commands piped in, as from a file. */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class GripperExampleTest {
    @TempDir
    Path dir;

    private Path world(String params) throws Exception {
        Path world = dir.resolve("pucks.xml");
        Files.writeString(world, """
                <world name="pucks" width="8000" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="1000" y="3000" th="0" params="%s"/>
                  <object x="1500" y="3000" color="red"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots").resolve(params)));
        return world;
    }

    private static String run(int port, String params, String commands) {
        ArRobot robot = new ArRobot("r1", "127.0.0.1", port, params);
        assertTrue(robot.blockingConnect(), robot.getConnectionError());
        robot.enableMotors();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        GripperExample example = new GripperExample(robot, new ArGripper(robot),
                new PrintStream(out, true, StandardCharsets.UTF_8));
        if (example.start()) {
            example.run(new BufferedReader(new StringReader(commands)));
        }
        robot.disconnect();
        return out.toString(StandardCharsets.UTF_8);
    }

    @Test
    void pipedKeysPickUpAPuckCarryItAMetreAndPutItDown() throws Exception {
        // 240 mm on, the puck's centre is 50 mm ahead of the body: between the paddles, on the inner beam
        String commands = "move 240\nc\nwait 25\nu\nwait 35\nmove 1000\nd\nwait 35\no\nwait 5\nmove -400\nfly\nq\n";
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world("p3dx-gripper.p")), 1,
                ServerOptions.loopback())) {
            CompletableFuture<String> example = Background.supply("gripper example",
                    () -> run(env.robotPort(), "p3dx-gripper", commands));
            String out = example.get(90, TimeUnit.SECONDS);
            env.await(60);

            assertTrue(out.contains("gripperExample: GripperType=GENIO"), out);
            assertTrue(out.contains("Lift:           maxed  Grip:            open  BreakBeam:      inner"), out);
            assertTrue(out.contains("Grip:          closed"), out);
            assertTrue(out.contains("Lift:           maxed  Grip:          closed  BreakBeam:      inner"), out);
            assertTrue(out.contains("gripperExample: 'fly' is not a command: " + GripperExample.COMMANDS), out);
            Snapshot.ObjectView puck = env.sim.snapshot().objects().get(0);
            assertNull(puck.heldBy());
            // held where it stood (50 mm ahead of the body is past touching it), carried the 1000 mm move
            assertEquals(2500, puck.x(), 1);
            assertEquals(3000, puck.y(), 1e-6);
        }
    }

    @Test
    void aRobotWithoutAGripperEndsTheExampleAsAriasDoes() throws Exception {
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world("p3dx.p")), 1,
                ServerOptions.loopback())) {
            String out = Background.supply("gripper example", () -> run(env.robotPort(), "p3dx", "c\nq\n"))
                    .get(90, TimeUnit.SECONDS);
            env.await(60);
            assertTrue(out.contains("gripperExample: GripperType=NOGRIPPER"), out);
            assertTrue(out.contains("gripperExample: Error: Robot does not have a gripper. Exiting."), out);
            assertFalse(out.contains("Closing gripper"), out);
        }
    }
}
