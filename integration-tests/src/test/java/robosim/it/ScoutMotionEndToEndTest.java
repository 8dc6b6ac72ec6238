package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.scout.StateVector.STATE_CONF_STEER;
import static robosim.scout.StateVector.STATE_CONF_X;
import static robosim.scout.StateVector.STATE_CONF_Y;
import static robosim.scout.StateVector.STATE_VEL_LEFT;
import static robosim.scout.StateVector.STATE_VEL_RIGHT;

import java.nio.file.Path;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;
import robosim.scout.NomadUnits;
import robosim.scout.Scout;

/** The Scout's motion calls over TCP: where vm, scout_vm and pr leave the robot. */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class ScoutMotionEndToEndTest {
    @TempDir
    Path dir;

    /** What a program saw, and where the Environment says the robot ended. */
    record Result(long[] seen, RobotSummary end) { }

    /** Runs one Scout at a pose in an empty 6 m room until its program returns. */
    private Result drive(double x, double y, double th, Function<Scout, long[]> program) throws Exception {
        Path world = ThreadedRun.world(dir, "room.xml", """
                <world name="room" width="6000" height="6000" boundary="true">
                  <robot name="s1" type="scout" x="%s" y="%s" th="%s" params="%%ROBOTS%%/scout.p"/>
                </world>
                """.formatted(x, y, th));
        try (ThreadedRun run = new ThreadedRun(world, 1, 0)) {
            Future<long[]> seen = run.robot(() -> {
                Scout s = new Scout("s1", "127.0.0.1", run.port());
                if (!s.connect_robot()) {
                    throw new IllegalStateException(s.getConnectionError());
                }
                long[] out = program.apply(s);
                s.disconnect_robot();
                return out;
            });
            long[] s = seen.get(60, TimeUnit.SECONDS);
            RunReport r = run.await();
            return new Result(s, r.robots().get(0));
        }
    }

    private static long[] conf(Scout s) {
        assertTrue(s.get_rc());
        return new long[] {s.State[STATE_CONF_X], s.State[STATE_CONF_Y], s.State[STATE_CONF_STEER]};
    }

    @Test
    void scoutVmWithoutSteeringDrivesStraightAtItsSpeed() throws Exception {
        Result r = drive(1000, 3000, 0, s -> {
            s.zr();
            s.scout_vm(100, 0);                  // 254 mm/s
            s.sleepSimulated(3000);
            s.gs();                              // 3.1 s after the command
            long right = s.State[STATE_VEL_RIGHT];
            long left = s.State[STATE_VEL_LEFT];
            s.st();
            assertTrue(s.ws(1, 1, 0, 5));
            long[] c = conf(s);
            return new long[] {right, left, c[0], c[1], c[2]};
        });
        assertEquals(100, r.seen()[0], "right wheel, 1/10 inch/s");
        assertEquals(100, r.seen()[1], "left wheel");
        // 3.1 s at 254 mm/s, less the 0.5 s spent reaching it at 500 mm/s²: about 723 mm
        assertEquals(NomadUnits.mmToTenthInch(254 * 3.1 - 254 * 254 / 1000.0), r.seen()[2], NomadUnits.mmToTenthInch(30));
        assertEquals(0, r.seen()[3], "no sideways drift");
        assertEquals(0, r.seen()[4], "no turn");
        assertEquals(3000, r.end().y(), 0.5);
        assertEquals(0, r.end().th(), 0.01);
    }

    @Test
    void vmTurnsAtTheRateItsWheelVelocitiesGive() throws Exception {
        Result r = drive(3000, 3000, 0, s -> {
            s.vm(100, 50, 0);                    // right 254 mm/s, left 127 mm/s
            s.sleepSimulated(1000);              // past the accelerations
            s.gs();
            long h1 = s.State[STATE_CONF_STEER];
            long right = s.State[STATE_VEL_RIGHT];
            long left = s.State[STATE_VEL_LEFT];
            s.sleepSimulated(1900);
            s.gs();                              // 2 s later
            long h2 = s.State[STATE_CONF_STEER];
            s.st();
            return new long[] {right, left, Math.floorMod(h2 - h1, 3600)};
        });
        assertEquals(100, r.seen()[0]);
        assertEquals(50, r.seen()[1]);
        // ARIA's rule with the Scout's DiffConvFactor: (254 - 127) / 2 · 0.005794 rad/s = 21.08 deg/s
        double expected = Math.toDegrees((254 - 127) / 2.0 * 0.005794) * 2;
        assertEquals(Math.round(expected * 10), r.seen()[2], 3);
    }

    @Test
    void prOfAMetreOnBothWheelsEndsWithin40mmOfAMetreAhead() throws Exception {
        Result r = drive(1000, 2000, 30, s -> {
            s.zr();
            s.pr(394, 394, 0);                   // 1000.76 mm
            boolean stopped = s.ws(1, 1, 0, 30);
            long[] c = conf(s);
            return new long[] {stopped ? 1 : 0, c[0], c[1], c[2]};
        });
        assertEquals(1, r.seen()[0], "ws saw both wheels stop");
        assertEquals(394, r.seen()[1], NomadUnits.mmToTenthInch(40));
        assertEquals(0, r.seen()[2], NomadUnits.mmToTenthInch(40));
        assertEquals(0, Math.floorMod(r.seen()[3] + 1800, 3600) - 1800, 10, "still heading the same way");
        double travelled = Math.hypot(r.end().x() - 1000, r.end().y() - 2000);
        assertEquals(1000, travelled, 40);
        assertEquals(30, Math.toDegrees(Math.atan2(r.end().y() - 2000, r.end().x() - 1000)), 1);
    }

    @Test
    void prWithOppositeWheelsTurnsInPlace() throws Exception {
        Result r = drive(3000, 3000, 0, s -> {
            s.zr();
            // 90 degrees: each wheel 900 · 0.118597 = 107 tenths of an inch round the wheelbase
            s.pr(107, -107, 0);
            s.ws(1, 1, 0, 30);
            long[] left = conf(s);
            s.pr(-213, 213, 0);                  // 180 degrees clockwise
            s.ws(1, 1, 0, 30);
            long[] back = conf(s);
            return new long[] {left[0], left[1], left[2], back[0], back[1], back[2]};
        });
        assertEquals(900, r.seen()[2], 15, "a quarter turn counter-clockwise");
        assertEquals(2700, r.seen()[5], 20, "then half a turn clockwise");
        for (int i : new int[] {0, 1, 3, 4}) {
            assertEquals(0, r.seen()[i], 4, "in place");
        }
        assertEquals(3000, r.end().x(), 10);
        assertEquals(3000, r.end().y(), 10);
    }
}
