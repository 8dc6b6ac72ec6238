package robosim.it;

import robosim.cli.Main;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import robosim.aria.ArRobot;
import robosim.examples.wander.Wander;
import robosim.protocol.Await;
import robosim.protocol.MessageCodec;
import robosim.protocol.Snapshot;
import robosim.protocol.recording.RecordingReader;
import robosim.cli.Background;

/**
 * {@code robosim env --record} and {@code robosim viewer --record}, run as a user runs them (in
 * this JVM, with captured output): both record the same steps.
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class RecordCommandsTest {
    private static final Pattern PORTS = Pattern.compile("robots on 127\\.0\\.0\\.1:(\\d+), viewers on 127\\.0\\.0\\.1:(\\d+)");

    @TempDir
    Path dir;

    private static CompletableFuture<Integer> start(StringWriter out, StringWriter err, String... args) {
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        return Background.supply("robosim " + args[0], () -> cl.execute(args));
    }

    private static Matcher awaitPorts(StringWriter out) {
        return Await.value(Await.PATIENCE, "the Environment says its ports", () -> {
            Matcher m = PORTS.matcher(out.toString());
            return m.find() ? m : null;
        });
    }

    private static List<byte[]> snapshotRecords(Path recording) throws Exception {
        MessageCodec codec = new MessageCodec();
        List<byte[]> encoded = new ArrayList<>();
        try (RecordingReader reader = RecordingReader.open(recording)) {
            Snapshot f;
            while ((f = reader.next()) != null) {
                encoded.add(codec.encode(f));
            }
        }
        return encoded;
    }

    @Test
    void theEnvironmentAndAViewerRecordTheSameSteps() throws Exception {
        Path envFile = dir.resolve("env.rsr");
        Path viewerFile = dir.resolve("viewer.rsr");
        StringWriter envOut = new StringWriter();
        StringWriter envErr = new StringWriter();
        CompletableFuture<Integer> env = start(envOut, envErr, "env",
                LocalEnvironment.root().resolve("testLoadFiles/environment/small-maze.xml").toString(), "--port", "0",
                "--viewer-port", "0", "--steps", "40", "--wait-viewers", "1", "--record", envFile.toString());
        Matcher ports = awaitPorts(envOut);
        int robotPort = Integer.parseInt(ports.group(1));
        StringWriter viewerOut = new StringWriter();
        StringWriter viewerErr = new StringWriter();
        CompletableFuture<Integer> viewer = start(viewerOut, viewerErr, "viewer", "--host", "127.0.0.1", "--port",
                ports.group(2), "--record", viewerFile.toString(), "--png-dir", dir.resolve("png").toString(), "--every", "20");
        for (String name : List.of("r1", "r2")) {
            Thread t = new Thread(() -> {
                ArRobot robot = new ArRobot(name, "127.0.0.1", robotPort, "p3dx");
                if (robot.blockingConnect()) {
                    robot.enableMotors();
                    new Wander(robot).run();
                }
            });
            t.setDaemon(true);
            t.start();
        }
        assertEquals(0, env.get(120, TimeUnit.SECONDS), envErr.toString());
        assertEquals(0, viewer.get(60, TimeUnit.SECONDS), viewerErr.toString());
        assertTrue(envOut.toString().contains("Recording: " + envFile.toAbsolutePath() + ", 41 steps in "), envOut.toString());
        assertTrue(viewerOut.toString().contains("3 PNG frames written"), viewerOut.toString());
        assertTrue(viewerOut.toString().contains("Recording: " + viewerFile.toAbsolutePath() + ", 41 steps in "),
                viewerOut.toString());
        List<byte[]> fromEnv = snapshotRecords(envFile);
        List<byte[]> fromViewer = snapshotRecords(viewerFile);
        assertEquals(41, fromEnv.size());
        assertEquals(41, fromViewer.size());
        for (int step = 1; step <= 40; step++) {
            assertArrayEquals(fromEnv.get(step), fromViewer.get(step), "step " + step);
        }
    }

    @Test
    void aRecordingThatCannotBeCreatedIsAOneLineError() {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        Path blocked = LocalEnvironment.root().resolve("testLoadFiles/environment/empty-room.xml").resolve("run.rsr");
        int exit = cl.execute("env", LocalEnvironment.root().resolve("testLoadFiles/environment/empty-room.xml").toString(),
                "--port", "0", "--viewer-port", "0", "--record", blocked.toString());
        assertEquals(1, exit);
        assertTrue(err.toString().startsWith("robosim env: cannot create recording " + blocked + ": "), err.toString());
    }
}
