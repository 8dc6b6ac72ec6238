package robosim.it;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.SynchronousQueue;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.protocol.Fuzz;
import robosim.protocol.MessageCodec;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.SnapshotListener;

/**
 * Honest robots run the same, step for step, while hostile peers attack the Environment they run
 * in (see {@link Fuzz} to replay the attack or run more): two wander robots in the empty room for
 * {@value #STEPS} steps, once in peace and once with {@link HostilePeers} connecting to the robot
 * and viewer ports during each of the first {@value #ROUNDS} steps. Each snapshot of the attacked
 * run must equal the peaceful run's, byte for byte; the run must end at its step limit; and every
 * line the Environment logs about a peer must be one line.
 *
 * <p>The attack is made while the step loop waits: a listener holds it after each snapshot until
 * that step's hostile peers have written, so that they reach the Environment during the run and
 * not after it, however fast the machine.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class HostilePeersFuzzTest {
    private static final int STEPS = 60;
    private static final int ROUNDS = 40;
    private static final int PEERS_PER_ROUND = 6;
    private static final MessageCodec CODEC = new MessageCodec();

    @Test
    void honestRobotsRunTheSameWhileHostilePeersAttack() throws Exception {
        List<byte[]> peaceful = run(null);
        assertEquals(STEPS + 1, peaceful.size(), "a snapshot for step 0 and each step");

        Fuzz.cases(0x5EED_0501L, 1, fuzz -> {
            Logger net = Logger.getLogger("robosim.env.net");
            boolean parents = net.getUseParentHandlers();
            net.setUseParentHandlers(false);
            try (LogCapture log = new LogCapture("robosim.env.net")) {
                List<byte[]> attacked = run(fuzz);

                assertEquals(peaceful.size(), attacked.size(), "steps run");
                for (int step = 0; step < peaceful.size(); step++) {
                    assertArrayEquals(peaceful.get(step), attacked.get(step), "the snapshot of step " + step);
                }
                assertFalse(log.warnings().isEmpty(), "the Environment closed hostile peers");
                for (String line : log.lines()) {
                    assertFalse(line.contains("\n") || line.contains("\r"), "one line: " + line);
                }
            } finally {
                net.setUseParentHandlers(parents);
            }
        });
    }

    /**
     * Runs the two wander robots, attacked by the case's hostile peers or by none.
     *
     * @return the snapshots, Smile-encoded, of step 0 and each step
     */
    private static List<byte[]> run(Fuzz attack) throws Exception {
        Gate gate = new Gate(attack != null);
        ServerOptions options = ServerOptions.loopback().withMaxSteps(STEPS);
        try (LocalEnvironment env = new LocalEnvironment(LocalEnvironment.shipped("empty-room.xml"), 1, options, gate);
             HostilePeers hostile = attack == null ? null : new HostilePeers(attack, env.robotPort(), env.viewerPort(),
                     List.of("r1", "r2", "r3", "robot", "r1 ", ""))) {
            List<Thread> robots = env.wanderers();
            if (hostile != null) {
                for (int round = 0; round < ROUNDS; round++) {
                    Long step = gate.arrived.poll(30, TimeUnit.SECONDS);
                    assertNotNull(step, "the run reached round " + round);
                    hostile.attack(step + 1, PEERS_PER_ROUND);
                    gate.released.put(Boolean.TRUE);
                }
            }
            RunReport report = env.await(60);
            assertEquals("step limit " + STEPS + " reached", report.endReason());
            assertTrue(report.robots().stream().allMatch(r -> r.distance() > 100), "the robots drove: " + report.robots());
            for (Thread t : robots) {
                t.join(10_000);
            }
            return gate.snapshots;
        }
    }

    /** Keeps the snapshots; when the run is attacked, holds the step loop after each of the first rounds' snapshots. */
    private static final class Gate implements SnapshotListener {
        final SynchronousQueue<Long> arrived = new SynchronousQueue<>();
        final SynchronousQueue<Boolean> released = new SynchronousQueue<>();
        final List<byte[]> snapshots = new ArrayList<>();
        private final boolean attacked;

        Gate(boolean attacked) {
            this.attacked = attacked;
        }

        @Override
        public void world(WorldDescription world) {
        }

        @Override
        public void snapshot(Snapshot snapshot) {
            snapshots.add(CODEC.encode(snapshot));
            if (attacked && snapshot.step() < ROUNDS) {
                try {
                    if (!arrived.offer(snapshot.step(), 30, TimeUnit.SECONDS)
                            || released.poll(30, TimeUnit.SECONDS) == null) {
                        throw new IllegalStateException("the attack did not come at step " + snapshot.step());
                    }
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }
    }
}
