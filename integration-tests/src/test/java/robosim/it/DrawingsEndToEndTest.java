package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArRobot;
import robosim.aria.ArUtil;
import robosim.cli.Background;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.Figure;
import robosim.protocol.Snapshot;
import robosim.viewer.draw.Drawings;

/** A robot's drawings over TCP: drawn by the program, refused past 8 layers, seen and cleared by a viewer. */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class DrawingsEndToEndTest {
    private static final Figure CELL = new Figure(Figure.CELLS, "", new double[] {0, 0, 1000, 1000});

    @TempDir
    Path dir;

    private static String program(int port) {
        ArRobot r1 = new ArRobot("r1", "127.0.0.1", port, "p3dx");
        r1.blockingConnect();
        ArUtil.sleep(300);
        for (int i = 1; i <= 9; i++) {
            r1.draw("layer" + i, List.of(CELL));
        }
        ArUtil.sleep(300);
        String error = r1.pollRequestError();
        r1.clearDrawing("layer1");
        r1.waitForRunExit();
        return error;
    }

    @Test
    void aViewerSeesWhatARobotDrawsAndTheNinthLayerIsRefused() throws Exception {
        Path world = dir.resolve("room.xml");
        Files.writeString(world, """
                <world name="room" width="6000" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="3000" y="3000" th="0" params="%s"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p")));
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world), 1,
                ServerOptions.loopback().withMaxSteps(20))) {
            SnapshotCollector viewer = new SnapshotCollector(env.viewerPort());
            CompletableFuture<String> robot = Background.supply("robot r1", () -> program(env.robotPort()));
            String error = robot.get(90, TimeUnit.SECONDS);
            env.await(60);

            assertTrue(error != null && error.contains("has 8 drawing layers") && error.contains("layer9"),
                    String.valueOf(error));
            Drawings drawings = new Drawings();
            int most = 0;
            for (Snapshot f : viewer.snapshots()) {
                drawings.add(f);
                most = Math.max(most, drawings.all().size());
            }
            assertEquals(8, most, "eight layers drawn, the ninth refused");
            List<String> left = new ArrayList<>();
            drawings.all().forEach(d -> left.add(d.layer()));
            assertEquals(List.of("layer2", "layer3", "layer4", "layer5", "layer6", "layer7", "layer8"), left,
                    "layer1 cleared");
        }
    }
}
