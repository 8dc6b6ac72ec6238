package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArRobot;
import robosim.cli.Background;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;

/**
 * A robot welcomed by the Environment but still stabilizing is not yet connected (ARIA's
 * isConnected), yet its link is up: its parameters are fixed, as ARIA's are once the connection is open.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class StabilizingRobotEndToEndTest {
    @TempDir
    Path dir;

    @Test
    void aParameterFileIsRefusedWhileTheRobotStabilizes() throws Exception {
        Path world = dir.resolve("room.xml");
        Files.writeString(world, """
                <world name="room" width="8000" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="1000" y="3000" th="0" params="%s"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.xml")));
        List<String> calls = new CopyOnWriteArrayList<>();
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world), 7, ServerOptions.loopback())) {
            CompletableFuture<Boolean> connected = Background.supply("robot r1", () -> {
                ArRobot robot = new ArRobot("r1", "127.0.0.1", env.robotPort(), "p3dx.xml");
                robot.setStabilizingTime(300);
                robot.addStabilizingCB(() -> calls.add("stabilizing: connected " + robot.isConnected()
                        + ", loadParamFile " + robot.loadParamFile("p3at.xml")));
                boolean ok = robot.blockingConnect();
                calls.add("connected " + robot.isConnected() + ", " + robot.getRobotSubType());
                robot.disconnect();
                return ok;
            });
            assertTrue(connected.get(60, TimeUnit.SECONDS));
        }
        assertEquals(List.of("stabilizing: connected false, loadParamFile false", "connected true, p3dx"), calls);
    }
}
