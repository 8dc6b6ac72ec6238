package robosim.it;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.core.RobotSummary;
import robosim.pioneer.Commands;
import robosim.pioneer.ConfigPacket;
import robosim.pioneer.LaserPacket;
import robosim.pioneer.PioneerClient;
import robosim.pioneer.PioneerPacket;
import robosim.pioneer.SimStat;
import robosim.pioneer.Sip;
import robosim.protocol.LaserReading;
import robosim.protocol.RobotState;
import robosim.protocol.SonarReading;

/** A robot served on a Pioneer port, driven and read by a client of the protocol as an ARIA program would. */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class PioneerPortTest {
    /** p3dx's factors, from its parameter file. */
    static final double DIST = 0.485;
    static final double ANGLE = 0.001534;

    @TempDir
    Path dir;

    static double x(Sip s) {
        return s.xPos() * DIST;
    }

    static double th(Sip s) {
        return Math.toDegrees(s.th() * ANGLE);
    }

    /** The newest SIP: the ones queued are read, and the last kept. */
    static Sip latest(PioneerClient c) throws InterruptedException {
        Sip last = null;
        PioneerPacket p;
        while ((p = c.receive(0)) != null) {
            if (p.id() == Commands.SIP_STOPPED || p.id() == Commands.SIP_MOVING) {
                last = Sip.decode(p);
            }
        }
        return last != null ? last : c.nextSip(2000);
    }

    /** Waits, reading SIPs, until the robot has been still for a few SIPs; returns the last. */
    static Sip settled(PioneerClient c) {
        Sip last = null;
        int still = 0;
        for (int i = 0; i < 200 && still < 5; i++) {
            Sip s = c.nextSip(2000);
            assertNotNull(s, "a SIP every step");
            still = s.leftVel() == 0 && s.rightVel() == 0 && last != null && s.xPos() == last.xPos()
                    && s.th() == last.th() ? still + 1 : 0;
            last = s;
        }
        return last;
    }

    @Test
    void theHandshakeNamesTheRobotAndConfigSaysItIsASimulator() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), false, code -> { });
             PioneerClient c = PioneerClient.connect("127.0.0.1", run.ports.portOf("r1"), 10_000)) {
            assertEquals("r1", c.identity().name());
            assertEquals("Pioneer", c.identity().robotClass());
            assertEquals("p3dx", c.identity().subclass());
            ConfigPacket config = c.open(10_000);
            assertEquals("SIM", config.serial());
            assertEquals("p3dx", config.subclass());
            assertEquals(100, config.sipCycle());
            assertEquals(2000, config.watchdog());
            assertEquals(2200, config.transVelMax());
            assertEquals(500, config.rotVelMax());
            assertTrue(config.frontSonar() && config.rearSonar());
        }
    }

    @Test
    void aSipCarriesTheRobotsOwnOdometrySonarAndFlags() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), false, code -> { });
             PioneerClient c = run.client("r1")) {
            Sip first = settled(c);
            // odometry starts at (0, 0, 0) in the robot's own frame, wherever it stands in the world
            assertEquals(0, first.xPos());
            assertEquals(0, first.yPos());
            assertEquals(0, first.th());
            assertEquals(129, first.battery(), "a full battery, 13.0 V, sagged 0.1 V by the electronics' 1 A");
            assertEquals(129, first.batteryX10());
            assertEquals(100, first.stateOfCharge());
            assertEquals(Sip.FLAG_SONARS, first.flags(), "sonar on, motors off until ENABLE 1");
            assertEquals(16, first.sonar().size());
            RobotState truth = run.env.sim.state("r1");
            for (Sip.SonarReading r : first.sonar()) {
                assertEquals(truth.get(SonarReading.PART).ranges()[r.index()], r.range(), 1, "sonar " + r.index());
            }

            c.send(Commands.comInt(Commands.ENABLE, 1));
            c.send(Commands.comInt(Commands.VEL, 300));
            Sip moving = null;
            for (int i = 0; i < 40; i++) {
                moving = c.nextSip(2000);
                if ((moving.leftVel() + moving.rightVel()) / 2 == 300) {
                    break;
                }
            }
            assertEquals(300, (moving.leftVel() + moving.rightVel()) / 2, "mm/s, VelConvFactor 1");
            assertTrue(moving.moving());
            assertEquals(Sip.FLAG_SONARS | Sip.FLAG_MOTORS, moving.flags());
            c.send(Commands.com(Commands.STOP));
            Sip stopped = settled(c);
            RobotSummary s = run.env.sim.summary("r1");
            assertEquals(s.x() - 3000, x(stopped), DIST, "XPOS × DistConvFactor is the distance travelled");
            assertEquals(0, stopped.yPos());
            assertEquals(0, stopped.stallBump());
        }
    }

    @Test
    void motionCommandsMoveAndTurnTheRobotInItsOwnFrame() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), false, code -> { });
             PioneerClient c = run.client("r1")) {
            c.send(Commands.comInt(Commands.ENABLE, 1));
            c.send(Commands.comInt(Commands.MOVE, 500));
            assertEquals(500, x(settled(c)), 10, "MOVE 500");
            c.send(Commands.comInt(Commands.HEAD, 90));
            assertEquals(90, th(settled(c)), 2, "HEAD 90");
            c.send(Commands.comInt(Commands.DHEAD, -45));
            assertEquals(45, th(settled(c)), 2, "DHEAD -45");
            RobotSummary s = run.env.sim.summary("r1");
            assertEquals(3500, s.x(), 10);
            assertEquals(45, s.th(), 2);

            c.send(Commands.com(Commands.SETO));
            Sip reset = settled(c);
            assertEquals(0, reset.xPos(), 1, "SETO puts the odometry at (0, 0, 0)");
            assertEquals(0, th(reset), 0.1);
        }
    }

    @Test
    void simSetPoseMovesTheTruePoseOnlyAndSimResetPutsTheRobotBack() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), false, code -> { });
             PioneerClient c = run.client("r1")) {
            c.send(Commands.comInt(Commands.ENABLE, 1));
            c.send(Commands.comInt(Commands.MOVE, 300));
            Sip before = settled(c);
            c.send(Commands.simSetPose(6000, 7000, 180));
            c.send(Commands.comInt(Commands.SIM_STAT, 1));
            PioneerPacket stat = c.await(p -> p.id() == Commands.SIMSTAT_PACKET, 5000);
            assertNotNull(stat, "SIM_STAT is answered");
            SimStat truth = SimStat.decode(stat);
            assertEquals(6000, truth.x());
            assertEquals(7000, truth.y());
            assertEquals(180, Math.abs(truth.th()));
            Sip after = settled(c);
            assertEquals(x(before), x(after), 1, "the odometry does not move with SIM_SET_POSE");

            c.send(Commands.com(Commands.SIM_RESET));
            Sip reset = settled(c);
            assertEquals(0, reset.xPos(), 1, "SIM_RESET puts the odometry at (0, 0, 0)");
            RobotSummary s = run.env.sim.summary("r1");
            assertEquals(3000, s.x(), 1e-6);
            assertEquals(3000, s.y(), 1e-6);
        }
    }

    @Test
    void aClientThatGoesSilentHasItsRobotStoppedByTheWatchdog() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), false, code -> { });
             PioneerClient c = PioneerClient.connect("127.0.0.1", run.ports.portOf("r1"), 10_000)) {
            c.open(10_000);
            c.send(Commands.comInt(Commands.ENABLE, 1));
            c.send(Commands.comInt(Commands.VEL, 200));
            // no PULSE from here: after 2 s the watchdog stops the robot; SIPs keep coming
            long start = System.nanoTime();
            Sip s = null;
            boolean moved = false;
            while (System.nanoTime() - start < TimeUnit.SECONDS.toNanos(5)) {
                s = c.nextSip(2000);
                assertNotNull(s, "SIPs keep coming to a silent client");
                moved |= s.leftVel() > 0;
            }
            assertTrue(moved);
            assertEquals(0, s.leftVel(), "stopped by the watchdog");
            // a packet brings the client back: the robot takes commands again
            c.send(Commands.comInt(Commands.VEL, 200));
            boolean again = false;
            for (int i = 0; i < 30 && !again; i++) {
                again = c.nextSip(2000).leftVel() > 0;
            }
            assertTrue(again);
        }
    }

    @Test
    void garbageBadPacketsAndAFloodOfPulsesNeverStopTheRun() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.roomForTwo(dir), false, code -> { });
             PioneerClient other = run.client("r2");
             PioneerClient c = run.client("r1")) {
            other.send(Commands.comInt(Commands.ENABLE, 1));
            other.send(Commands.comInt(Commands.VEL, 100));
            c.sendRaw(new byte[] {1, 2, 3, 4, 5, 6, 7, 8});
            byte[] bad = Commands.comInt(Commands.VEL, 900).encode();
            bad[bad.length - 1] ^= 0x55;
            c.sendRaw(bad);
            c.sendRaw(new byte[] {(byte) 0xFA, (byte) 0xFB, (byte) 0xFF, 11, 0x3B});
            c.sendRaw(new PioneerPacket(Commands.VEL, new byte[] {0x3B}).encode()); // an argument cut short
            for (int i = 0; i < 2000; i++) {
                c.send(Commands.com(Commands.PULSE));
            }
            c.send(Commands.comInt(Commands.ENABLE, 1));
            c.send(Commands.comInt(Commands.MOVE, 200));
            // the flood is read no faster than the input budget: the move comes after it
            for (int i = 0; i < 100 && c.nextSip(2000).leftVel() == 0; i++) {
                assertFalse(c.isClosed());
            }
            assertEquals(200, x(settled(c)), 10, "the commands after the garbage are carried out");
            assertFalse(c.isClosed());
            Sip s = latest(other);
            assertEquals(100, s.leftVel(), "the other robot drove on meanwhile");
            assertTrue(x(s) > 100, "the other robot drove on meanwhile: " + x(s));
        }
    }

    @Test
    void theLaserSendsItsScanInPacketsOfTheFieldOfViewAsked() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), false, code -> { });
             PioneerClient c = run.client("r1")) {
            c.send(Commands.comInt(Commands.SIM_LRF_ENABLE, 1));
            int[] scan = scan(c, Commands.LASER_PACKET);
            assertEquals(181, scan.length);
            int[] truth = run.env.sim.state("r1").get(LaserReading.PART).ranges();
            assertArrayEquals(truth, scan, "the Environment's scan, −90° to 90° at 1°");
            // ARIA's simulated laser configures itself with the older simulator's commands
            c.send(Commands.comInt(36, -45));
            c.send(Commands.comInt(37, 45));
            c.send(Commands.comInt(38, 50));
            c.send(Commands.comInt(35, 2));
            int[] narrow = scan(c, Commands.LASER_EXTENDED_PACKET);
            assertEquals(181, narrow.length, "−45° to 45° at 0.5°");
            int[] fine = run.env.sim.state("r1").get(LaserReading.PART).ranges();
            assertEquals(fine[180], narrow[90], "the reading dead ahead");
        }
    }

    /** Reads laser packets of one kind until a whole scan has come. */
    private static int[] scan(PioneerClient c, int id) {
        int[] ranges = null;
        int got = 0;
        for (int i = 0; i < 400; i++) {
            PioneerPacket p = c.await(q -> q.id() == id, 3000);
            assertNotNull(p, "laser packets come");
            LaserPacket l = LaserPacket.decode(p);
            if (l.first() == 0) {
                ranges = new int[l.total()];
                got = 0;
            }
            if (ranges == null) {
                continue;
            }
            System.arraycopy(l.ranges(), 0, ranges, l.first(), l.ranges().length);
            got += l.ranges().length;
            if (got == ranges.length) {
                return ranges;
            }
        }
        throw new AssertionError("no whole scan");
    }

    @Test
    void aPortTakesOneClientAtATimeAndSimExitIsRefusedByDefault() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), false, code -> { });
             PioneerClient c = run.client("r1")) {
            java.io.IOException refused = org.junit.jupiter.api.Assertions.assertThrows(java.io.IOException.class,
                    () -> PioneerClient.connect("127.0.0.1", run.ports.portOf("r1"), 3000).close());
            assertTrue(refused.getMessage().contains("SYNC0"), refused.getMessage());
            c.send(Commands.comInt(Commands.SIM_EXIT, 0));
            assertNotNull(c.nextSip(2000));
            assertNotNull(c.nextSip(2000), "the run goes on");
        }
    }

    @Test
    void theNextClientFindsTheOdometryAtZeroAgain() throws Exception {
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), false, code -> { })) {
            try (PioneerClient c = run.client("r1")) {
                c.send(Commands.comInt(Commands.ENABLE, 1));
                c.send(Commands.comInt(Commands.MOVE, 400));
                assertEquals(400, x(settled(c)), 10);
                c.disconnect();
            }
            try (PioneerClient c = run.client("r1")) {
                Sip s = settled(c);
                assertEquals(0, s.xPos());
                assertNull(c.endReason());
            }
        }
    }

    @Test
    void allowedSimExitEndsTheRunWithTheCode() throws Exception {
        java.util.concurrent.CompletableFuture<Integer> exit = new java.util.concurrent.CompletableFuture<>();
        try (PioneerRun run = new PioneerRun(PioneerRun.room(dir), true, exit::complete);
             PioneerClient c = run.client("r1")) {
            c.send(Commands.comInt(Commands.SIM_EXIT, 3));
            assertEquals(3, exit.get(10, TimeUnit.SECONDS));
        }
    }

}
