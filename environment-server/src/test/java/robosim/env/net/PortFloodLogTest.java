package robosim.env.net;

import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.IntFunction;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.env.core.Simulation;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.CommsUpdate;
import robosim.protocol.ControlHello;
import robosim.protocol.ControlRequest;
import robosim.protocol.FrameReader;
import robosim.protocol.Await;
import robosim.protocol.CapturedLog;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotParameters;
import robosim.protocol.RunSecret;
import robosim.protocol.ViewerHello;
import robosim.protocol.Welcome;

/**
 * A live Environment (with a run secret, waiting for its robots) attacked on each of its ports by
 * what a hostile client can repeat as fast as it likes: each attack costs a handful of log lines,
 * one a kind a second and the count of the rest, whatever the number of attempts, and no line
 * carries a control character or the attacker's long text.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class PortFloodLogTest {
    private static final String SECRET = RunSecret.create();
    private static final String WRONG = RunSecret.create();
    /** A name of 100 000 characters with ESC and BEL in it. */
    private static final String HUGE = "\u001b[2J\u0007" + "x".repeat(100_000);

    private CapturedLog log;
    private final MessageCodec codec = new MessageCodec();
    private Simulation sim;
    private EnvironmentServer server;
    private Thread loop;

    @BeforeEach
    void start() throws IOException {
        Path root = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (!Files.isDirectory(root.resolve("testLoadFiles"))) {
            root = root.getParent();
        }
        sim = new Simulation(WorldReader.read(root.resolve("testLoadFiles/environment/empty-room.xml")), 1);
        server = new EnvironmentServer(sim, ServerOptions.loopback().withAccess(Access.secret(SECRET)));
        server.bind();
        loop = new Thread(() -> {
            try {
                server.run();
            } catch (InterruptedException | RuntimeException e) {
                // closed by the test: the run did not start
            }
        }, "environment");
        loop.setDaemon(true);
        loop.start();
        log = new CapturedLog("robosim.env");
    }

    @AfterEach
    void stop() throws InterruptedException {
        log.close();
        server.close();
        loop.interrupt();
        loop.join(10_000);
    }

    @Test
    void wrongSecretViewerHellos() throws Exception {
        attack(server.viewerPort(), 2000, i -> frame(new ViewerHello("v"
                + i, WRONG)), "refused connections on the viewer port");
    }

    @Test
    void wrongSecretControlHellos() throws Exception {
        attack(server.viewerPort(), 2000, i -> frame(new ControlHello(i % 10 == 0 ? HUGE : "c"
                + i, WRONG)), "refused connections on the viewer port");
    }

    @Test
    void wrongSecretRobotHellos() throws Exception {
        attack(server.robotPort(), 1000, i -> frame(hello("r1", WRONG)), "refused robot hellos");
    }

    @Test
    void unknownAndUnlawfulRobotNames() throws Exception {
        attack(server.robotPort(), 500, i -> frame(hello(i % 10 == 0 ? HUGE : "r" + (i
                + 3), SECRET)), "refused robot hellos");
    }

    @Test
    void duplicateRobotNames() throws Exception {
        try (Socket r1 = new Socket("127.0.0.1", server.robotPort())) {
            new FrameWriter(r1.getOutputStream(), codec).write(hello("r1", SECRET));
            assertInstanceOf(Welcome.class, new FrameReader(r1.getInputStream(), codec, 1 << 24).read());
            attack(server.robotPort(), 500, i -> frame(hello("r1", SECRET)), "refused robot hellos");
        }
    }

    @Test
    void badParametersInRobotHellos() throws Exception {
        RobotParameters p = sim.world().robots().get(0).parameters();
        RobotParameters bad = new RobotParameters(p.robotClass(), p.subclass(), p.robotRadius(), p.robotWidth(),
                p.robotLengthFront(), p.robotLengthRear(), Double.NaN, p.maxRVelocity(), p.transAccel(),
                p.transDecel(), p.rotAccel(), p.rotDecel(), p.diffConvFactor(), p.sonarMaxRange(), p.sonarUnits(),
                p.laserX(), p.laserY(), p.laserTh(), p.laserMaxRange(), p.shape());
        attack(server.robotPort(), 500, i -> frame(new RobotHello("r2", i % 10 == 0 ? HUGE : "pioneer", bad, SECRET)),
                "refused robot hellos");
    }

    @Test
    void badFrames() throws Exception {
        byte[] garbage = ("{\"type\":\"" + HUGE.substring(0, 5000) + "\"}").getBytes(StandardCharsets.UTF_8);
        attack(server.robotPort(), 1000, i -> framed(garbage),
                "closed connections without a hello on the robot port");
    }

    @Test
    void framesOverTheLimit() throws Exception {
        byte[] header = ByteBuffer.allocate(4).putInt(64 << 20).array();
        attack(server.robotPort(), 1000, i -> header, "closed connections without a hello on the robot port");
    }

    @Test
    void controlRequestsWithBadValuesAndChangesEachTime() throws Exception {
        try (Socket c = new Socket("127.0.0.1", server.viewerPort())) {
            c.setSoTimeout(20_000);
            FrameWriter out = new FrameWriter(c.getOutputStream(), codec);
            FrameReader in = new FrameReader(c.getInputStream(), codec, 1 << 24);
            out.write(new ControlHello("ctl", SECRET));
            long started = System.nanoTime();
            for (int i = 0; i < 2000; i++) {
                out.write(i % 3 == 0 ? new ControlRequest(i, "step", List.of(HUGE))
                        : i % 3 == 1 ? new ControlRequest(i, HUGE, List.of())
                        : new CommsUpdate(1000.0 + i, null, null, null, null));
                in.read();
            }
            bounded(started, "refused control requests");
        }
    }

    private RobotHello hello(String name, String token) {
        return new RobotHello(name, "pioneer", sim.world().robots().get(0).parameters(), token);
    }

    private byte[] frame(Message m) {
        ByteBuffer b = FrameWriter.frame(codec, m);
        byte[] bytes = new byte[b.remaining()];
        b.get(bytes);
        return bytes;
    }

    private static byte[] framed(byte[] payload) {
        return ByteBuffer.allocate(4 + payload.length).putInt(payload.length).put(payload).array();
    }

    /**
     * Connects {@code times} times, sends the bytes and waits for the Environment to close the
     * connection, then checks the log stayed bounded.
     */
    private void attack(int port, int times, IntFunction<byte[]> bytes, String kind) throws Exception {
        long started = System.nanoTime();
        byte[] drain = new byte[1 << 16];
        for (int i = 0; i < times; i++) {
            try (Socket s = new Socket("127.0.0.1", port)) {
                s.setSoTimeout(20_000);
                s.getOutputStream().write(bytes.apply(i));
                InputStream in = s.getInputStream();
                while (in.read(drain) >= 0) {
                    // until the Environment closes it
                }
            } catch (IOException reset) {
                // the Environment may close before it has read all: that is a close too
            }
        }
        bounded(started, kind);
    }

    /** Waits for the count line of the kind, then checks the lines are few, short and free of control characters. */
    private void bounded(long started, String kind) {
        Await.until(Duration.ofSeconds(10), "a count line of " + kind,
                () -> snapshot().stream().anyMatch(l -> l.contains(" more " + kind + " in the last 1000 ms")));
        long seconds = TimeUnit.NANOSECONDS.toSeconds(System.nanoTime() - started) + 1;
        List<String> got = snapshot();
        // a whole line and a count line a second for each kind, and the lines that come once
        assertTrue(got.size() <= 8 + 4 * seconds, got.size() + " lines in " + seconds + " s: " + got);
        for (String line : got) {
            assertTrue(line.length() < 1000, () -> "a long line: " + line.substring(0, 200));
            assertTrue(line.chars().noneMatch(ch -> ch < 0x20 || ch == 0x7f), "a control character in " + line);
        }
    }

    private List<String> snapshot() {
        return log.lines();
    }
}
