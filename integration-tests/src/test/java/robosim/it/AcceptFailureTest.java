package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.cli.Main;
import robosim.protocol.Await;

/**
 * When the Environment's file table is full, {@code accept} fails as long as connections wait: the
 * Environment pauses accepting instead of spinning, logs the failure once and, when the period
 * ends, how many more there were, and takes robots again once descriptors are free.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class AcceptFailureTest {
    @TempDir
    Path dir;

    @Test
    void acceptFailuresAreLoggedOnceWithACountAndTheEnvironmentRecovers() throws Exception {
        Path sh = Path.of("/bin/sh");
        if (!Files.isExecutable(sh)) {
            System.err.println("AcceptFailureTest SKIPPED: no /bin/sh to lower the Environment's file limit with ulimit");
            Assumptions.abort("no /bin/sh to lower the Environment's file limit with ulimit");
        }
        Path log = dir.resolve("env.log");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        String world = LocalEnvironment.root().resolve("testLoadFiles/environment/empty-room.xml").toString();
        String cmd = "ulimit -n 200 && exec \"$0\" -Djava.awt.headless=true -cp \"$1\" " + Main.class.getName()
                + " env \"$2\" --port 0 --viewer-port 0 --no-token --max-pending 100000 --hello-deadline 100000"
                + " --steps 1 --connect-timeout 100";
        Process env = new ProcessBuilder(sh.toString(), "-c", cmd, java, System.getProperty("java.class.path"), world)
                .redirectErrorStream(true).redirectOutput(log.toFile()).start();
        List<Socket> flood = new ArrayList<>();
        try {
            int port = awaitPort(log, env);
            // more connections than the Environment has descriptors for, until its listen backlog is full too
            for (int i = 0; i < 400; i++) {
                Socket s = new Socket();
                try {
                    s.connect(new InetSocketAddress("127.0.0.1", port), 2_000);
                } catch (IOException full) {
                    s.close();
                    break;
                }
                flood.add(s);
            }
            assertTrue(flood.size() > 200, "connections made: " + flood.size());
            String text = awaitLine(log, env, Pattern.compile("(\\d+) more accept failures in the last 10000 ms,"
                    + " not logged one by one"));
            long failures = text.lines().filter(l -> l.contains("accepting a robot connection failed:")).count();
            assertTrue(failures >= 1 && failures <= 3, "one line a period, not one a failure:\n" + text);
            assertTrue(text.contains("Too many open files"), text);
            for (Socket s : flood) {
                s.close();
            }
            flood.clear();
            // descriptors are free again: the world's robots get in and the run ends
            try (RawPeer r1 = new RawPeer(port); RawPeer r2 = new RawPeer(port)) {
                var sim = new robosim.env.core.Simulation(LocalEnvironment.shipped("empty-room.xml"), 1);
                for (var peer : List.of(r1, r2)) {
                    peer.send(new robosim.protocol.RobotHello(peer == r1 ? "r1" : "r2", "pioneer",
                            sim.world().robots().get(0).parameters()));
                }
                assertTrue(r1.read() instanceof robosim.protocol.Welcome, Files.readString(log));
                assertTrue(r2.read() instanceof robosim.protocol.Welcome, Files.readString(log));
            }
            assertTrue(env.waitFor(60, TimeUnit.SECONDS), Files.readString(log));
            assertEquals(0, env.exitValue(), Files.readString(log));
        } finally {
            for (Socket s : flood) {
                s.close();
            }
            env.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }

    private static int awaitPort(Path log, Process env) throws Exception {
        Matcher m = Pattern.compile("robots on 127\\.0\\.0\\.1:(\\d+)").matcher(awaitLine(log, env,
                Pattern.compile("robots on 127\\.0\\.0\\.1:(\\d+)")));
        m.find();
        return Integer.parseInt(m.group(1));
    }

    /** Waits (bounded) until the log holds a match; returns the whole log. */
    private static String awaitLine(Path log, Process env, Pattern wanted) {
        boolean inTime = Await.within(Duration.ofSeconds(60), () -> wanted.matcher(read(log)).find() || !env.isAlive());
        String text = read(log);
        if (wanted.matcher(text).find()) {
            return text;
        }
        throw new AssertionError((inTime ? "the Environment ended (" + env.exitValue() + ") before '" + wanted + "'"
                : "no '" + wanted + "' within 60 s") + ":\n" + text);
    }

    private static String read(Path log) {
        try {
            return Files.readString(log);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
