package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.pioneer.Commands;
import robosim.pioneer.PioneerClient;
import robosim.pioneer.PioneerPacket;
import robosim.pioneer.Sip;
import robosim.protocol.Await;

/**
 * A client that floods its Pioneer port with commands slows only itself: its commands coalesce to
 * the latest of each kind a step, its input is read no faster than a budget, the other robots step
 * on, and the log gets a line a second of each kind, quoting the client's text escaped.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class PioneerFloodTest {
    @TempDir
    Path dir;

    private static byte[] repeated(PioneerPacket p, int times) {
        byte[] one = p.encode();
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        for (int i = 0; i < times; i++) {
            b.write(one, 0, one.length);
        }
        return b.toByteArray();
    }

    @Test
    void aBurstOfMotionCommandsWithinAStepEndsAtItsLatest() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), false, code -> { });
             PioneerClient c = run.client("r1")) {
            c.send(Commands.comInt(Commands.ENABLE, 1));
            ByteArrayOutputStream burst = new ByteArrayOutputStream();
            for (int v = -150; v <= 150; v += 2) {
                burst.writeBytes(Commands.comInt(Commands.VEL, v).encode());
                burst.writeBytes(Commands.comInt(Commands.RVEL, -v).encode());
            }
            burst.writeBytes(Commands.comInt(Commands.RVEL, 0).encode());
            burst.writeBytes(Commands.comInt(Commands.VEL, 250).encode());
            c.sendRaw(burst.toByteArray());
            Sip s = null;
            for (int i = 0; i < 50 && (s == null || s.leftVel() != 250); i++) {
                s = c.nextSip(2000);
                assertNotNull(s);
            }
            assertEquals(250, s.leftVel(), "the latest VEL wins");
            assertEquals(250, s.rightVel(), "and the latest RVEL: no turn");
        }
    }

    @Test
    void aClientFloodingMotionCommandsSlowsOnlyItselfAndIsClosedWhenItKeepsOn() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.roomForTwo(dir), false, code -> { });
             LogCapture logs = new LogCapture("robosim");
             PioneerClient honest = run.client("r2");
             PioneerClient flooder = run.client("r1")) {
            honest.send(Commands.comInt(Commands.ENABLE, 1));
            honest.send(Commands.comInt(Commands.VEL, 100));
            flooder.send(Commands.comInt(Commands.ENABLE, 1));
            byte[] batch = repeated(Commands.comInt(Commands.VEL, 300), 500);
            AtomicLong sent = new AtomicLong();
            java.util.concurrent.atomic.AtomicReference<String> why = new java.util.concurrent.atomic.AtomicReference<>();
            Thread flood = new Thread(() -> {
                long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
                try {
                    while (System.nanoTime() < until) {
                        flooder.sendRaw(batch);
                        sent.addAndGet(500);
                    }
                } catch (IOException closed) {
                    why.set(closed.toString()); // the port closed it
                }
            }, "flood");
            flood.start();
            double startX = PioneerPortTest.x(PioneerPortTest.latest(honest));
            long started = System.nanoTime();
            while (System.nanoTime() - started < TimeUnit.SECONDS.toNanos(3)) {
                assertNotNull(flooder.nextSip(2000), "the flooder is slowed, not closed, at first");
            }
            Sip during = PioneerPortTest.latest(honest);
            assertTrue(PioneerPortTest.x(during) - startX > 100, "the honest robot drove on at 100 mm/s through the"
                    + " flood: " + startX + " -> " + PioneerPortTest.x(during));
            assertTrue(sent.get() > 6000, "it sent more than its budget of 2000 packets a second: " + sent.get());
            flood.join(TimeUnit.SECONDS.toMillis(30));
            assertFalse(flood.isAlive(), "a flood that keeps on is closed");
            assertTrue(run.env.sim.robotNames().contains("r1"), "its robot stays in the run");
            assertNotNull(PioneerPortTest.latest(honest), "the honest client is still sent its status");
            // the line comes as the port closes the connection
            Await.within(Duration.ofSeconds(10),
                    () -> logs.lines().stream().anyMatch(l -> l.contains("left: it has sent more than 200 packets")));
            List<String> lines = logs.lines();
            assertTrue(lines.stream().anyMatch(l -> l.contains("left: it has sent more than 200 packets")),
                    why.get() + " " + flooder.endReason() + " " + lines);
            assertFalse(lines.stream().anyMatch(l -> l.contains("exceeds the limit")), lines.toString());
            // the first line whole and then a count a second (or only counts, when a flood of the test
            // before was still being counted)
            long budgetLines = lines.stream().filter(l -> l.contains("it is read no faster than that")
                    || l.contains("input budgets exceeded")).count();
            assertTrue(budgetLines >= 1 && budgetLines <= 9, "a line a second: " + lines);
            try (PioneerClient next = run.client("r1")) {
                assertNotNull(next.nextSip(2000), "the next client gets the port");
            }
        }
    }

    @Test
    void soundsMessagesAndMalformedCommandsCostALineASecondAndQuoteTextEscaped() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), false, code -> { });
             LogCapture logs = new LogCapture("robosim.pioneer");
             PioneerClient c = run.client("r1")) {
            ByteArrayOutputStream flood = new ByteArrayOutputStream();
            byte[] say = new PioneerPacket(Commands.SAY, new byte[] {1, 2, 3}).encode();
            byte[] message = Commands.comStr(Commands.SIM_MESSAGE, "\u001b[2J\u0007owned").encode();
            byte[] malformed = new PioneerPacket(Commands.VEL, new byte[] {0x3B}).encode();
            for (int i = 0; i < 1000; i++) {
                flood.writeBytes(say);
                flood.writeBytes(message);
                flood.writeBytes(malformed);
            }
            c.sendRaw(flood.toByteArray());
            c.send(Commands.comInt(Commands.ENABLE, 1));
            c.send(Commands.comInt(Commands.VEL, 200));
            Sip s = null;
            for (int i = 0; i < 600 && (s == null || s.leftVel() != 200); i++) {
                s = c.nextSip(2000);
                assertNotNull(s, "the run goes on");
            }
            assertEquals(200, s.leftVel(), "the whole flood was read, and the commands after it");
            for (int i = 0; i < 30 && logs.lines().stream().noneMatch(l -> l.contains("more sounds")); i++) {
                assertNotNull(c.nextSip(2000)); // the count comes when the second is over
            }
            List<String> lines = logs.lines();
            assertTrue(lines.size() < 40, "3001 packets that each log a line cost a line a second of each kind: "
                    + lines.size() + " lines: " + lines);
            assertTrue(lines.stream().anyMatch(l -> l.contains("\\u001b[2J\\u0007owned")), "escaped: " + lines);
            assertFalse(lines.stream().anyMatch(l -> l.chars().anyMatch(ch -> ch < 0x20)), "no control character");
            assertTrue(lines.stream().anyMatch(l -> l.matches("\\d+ more sounds \\(SAY\\) of robot r1 in the last.*")),
                    "the sounds not logged are counted: " + lines);
        }
    }
}
