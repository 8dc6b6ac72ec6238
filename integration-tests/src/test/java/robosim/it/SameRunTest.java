package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Timeout;
import robosim.examples.goldfinder.Gold;
import robosim.examples.scoutwander.ScoutWander;
import robosim.examples.wander.Wander;
import robosim.protocol.MessageCodec;
import robosim.protocol.Snapshot;

/**
 * The same world, seed and robot programs give the same run, byte for byte, from one version of
 * RoboSim to the next: each run's snapshots, as the wire encodes them, hash to the digest recorded
 * when the test was written. A change to the code that changes a run (a sensor reading, a pose, a
 * message, a drawing, the order of anything) fails here; one that is meant to must say so by
 * recording the new digest, with the reason in its commit. Each run is made twice, its robots
 * reaching the Environment over TCP and in-process: the digests are the same.
 */
@Timeout(value = 4, unit = TimeUnit.MINUTES)
class SameRunTest {
    private static final Path WORLDS = LocalEnvironment.root().resolve("testLoadFiles/environment");
    private static final MessageCodec CODEC = new MessageCodec();

    /** A robot program for a robot of the run, given its name and the Environment's port. */
    private interface Program {
        void run(String name, String port) throws Exception;
    }

    /** @return the SHA-256 of every snapshot of the run, in order, as the wire encodes them */
    private static String digest(Path world, long seed, long steps, List<String> robots, Program program,
                                 boolean inProcess) throws Exception {
        try (ThreadedRun run = new ThreadedRun(world, seed, steps, inProcess)) {
            String port = Integer.toString(run.port());
            List<Future<Object>> started = new ArrayList<>();
            for (String r : robots) {
                started.add(run.robot(() -> {
                    program.run(r, port);
                    return null;
                }));
            }
            assertEquals(steps, run.await().steps());
            // the robots of this JVM share one link: in-process when the Environment admits them so
            assertEquals(inProcess ? 1 : 0, run.env.server.inProcessLinks());
            for (Future<Object> p : started) {
                p.get(30, TimeUnit.SECONDS);
            }
            MessageDigest sha = MessageDigest.getInstance("SHA-256");
            synchronized (run.snapshots) {
                for (Snapshot s : run.snapshots) {
                    sha.update(CODEC.encode(s));
                }
                return run.snapshots.size() + " snapshots, " + HexFormat.of().formatHex(sha.digest());
            }
        }
    }

    @ParameterizedTest(name = "in-process {0}")
    @ValueSource(booleans = {false, true})
    void twoWanderersInTheSmallMaze(boolean inProcess) throws Exception {
        assertEquals("401 snapshots, 217520dab2ffe49cce806409809cfa8cf32d6cde84084a21e4dd0291579982b6",
                digest(WORLDS.resolve("small-maze.xml"), 1, 400, List.of("r1", "r2"),
                (name, port) -> Wander.main(new String[] {name, "127.0.0.1", port}), inProcess));
    }

    @ParameterizedTest(name = "in-process {0}")
    @ValueSource(booleans = {false, true})
    void aScoutAndTwoPioneersWandering(boolean inProcess) throws Exception {
        assertEquals("301 snapshots, f54a08b03f5ce0f4eeee977ca3f0b225c81688d91f30622132b2d138e46cc5d9",
                digest(WORLDS.resolve("mixed-team.xml"), 11, 300, List.of("s1", "r1", "r2"),
                (name, port) -> {
                    if (name.startsWith("s")) {
                        ScoutWander.main(new String[] {name, "127.0.0.1", port});
                    } else {
                        Wander.main(new String[] {name, "127.0.0.1", port});
                    }
                }, inProcess));
    }

    @ParameterizedTest(name = "in-process {0}")
    @ValueSource(booleans = {false, true})
    void aGoldFinderTeamTalkingAndDrawingInAMaze(boolean inProcess) throws Exception {
        assertEquals("201 snapshots, 085cc715cd87df6ffecf0ae73bfd35a33eca725f12d9c66a06ef8887742c786b",
                digest(WORLDS.resolve("maze-small.xml"), 3, 200,
                List.of("r1", "r2", "r3", "r4", "r5", "r6", "r7", "r8"), (name, port) -> {
                    Gold g = new Gold(name, "127.0.0.1", Integer.parseInt(port));
                    if (g.blockingConnect()) {
                        g.search();
                        g.disconnect();
                    }
                }, inProcess));
    }
}
