package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArAction;
import robosim.aria.ArActionAvoidFront;
import robosim.aria.ArActionConstantVelocity;
import robosim.aria.ArActionDesired;
import robosim.aria.ArActionLimiterBackwards;
import robosim.aria.ArActionLimiterForwards;
import robosim.aria.ArActionStallRecover;
import robosim.aria.ArRobot;
import robosim.aria.ArSonarDevice;
import robosim.cli.Background;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.examples.wander.ActionWander;

/**
 * ARIA's standard actions driving a robot on a live Environment, in a literal 8 × 6 m room without
 * noise: each as ARIA's source says it behaves (ArActionAvoidFront.cpp, ArActionStallRecover.cpp,
 * ArActionLimiterForwards.cpp, ArActionLimiterBackwards.cpp), and ARIA's wander.cpp built from them.
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class ActionsEndToEndTest {
    private static final double ROOM_WIDTH = 8000;
    /** The faces of the room's 100 mm boundary walls. */
    private static final double EAST_WALL = ROOM_WIDTH - 100;
    private static final double WEST_WALL = 100;
    /** The p3dx's figures (testLoadFiles/robots/p3dx.xml). */
    private static final double LENGTH = 511;
    private static final double FRONT = 210;
    private static final double REAR = 301;

    @TempDir
    Path dir;

    /** The robot as it was at one cycle. */
    private record Sample(long timeMs, double x, double y, double th, double vel, boolean stalled) { }

    /**
     * Runs one robot with the given actions for a while, sampling its odometry pose (there is no noise,
     * so odometry is the true pose) each cycle.
     */
    private List<Sample> run(double x, double y, double th, long ms, Consumer<ArRobot> actions) throws Exception {
        Path world = dir.resolve("room.xml");
        Files.writeString(world, """
                <world name="room" width="%.0f" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="%.0f" y="%.0f" th="%.0f" params="%s"/>
                </world>
                """.formatted(ROOM_WIDTH, x, y, th, LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.xml")));
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world), 3, ServerOptions.loopback())) {
            CompletableFuture<List<Sample>> samples = Background.supply("robot r1", () -> {
                ArRobot robot = ActionPrograms.connect(env, "r1");
                List<Sample> seen = new ArrayList<>();
                robot.addUserTask("sample", 50, () -> seen.add(new Sample(robot.getSimTimeMs(), robot.getX(),
                        robot.getY(), robot.getTh(), robot.getVel(), robot.isStalled())));
                robot.lock();
                try {
                    actions.accept(robot);
                } finally {
                    robot.unlock();
                }
                robot.sleepSimulated(ms);
                robot.disconnect();
                return seen;
            });
            List<Sample> s = samples.get(120, TimeUnit.SECONDS);
            env.await(60);
            return s;
        }
    }

    private static Sample last(List<Sample> s) {
        return s.get(s.size() - 1);
    }

    @Test
    void avoidFrontTurnsAwayFromAWallAheadAndNeverTouchesIt() throws Exception {
        // heading 10° to the east wall: its nearest echo is to the right (−10°), so the robot turns left
        List<Sample> s = run(6000, 3000, 10, 10_000, robot -> {
            robot.addRangeDevice(new ArSonarDevice());
            robot.addAction(new ArActionAvoidFront(), 50);
            robot.addAction(new ArActionConstantVelocity("go", 300), 25);
        });

        assertTrue(s.stream().noneMatch(Sample::stalled), "it never touched the wall");
        double maxX = s.stream().mapToDouble(Sample::x).max().orElseThrow();
        assertTrue(maxX + FRONT < EAST_WALL, "stayed off the wall: front reached " + (maxX + FRONT));
        double turned = s.stream().mapToDouble(Sample::th).max().orElseThrow() - 10;
        assertTrue(turned > 45, "turned left, away from the wall, by " + turned + "°");
    }

    @Test
    void stallRecoverBacksOffAndTurnsWhenTheRobotStallsAgainstAWall() throws Exception {
        List<Sample> s = run(7000, 3000, 0, 20_000, robot -> {
            robot.addRangeDevice(new ArSonarDevice());
            robot.addAction(new ArActionStallRecover(), 100);
            robot.addAction(new ArActionConstantVelocity("go", 300), 25);
        });

        int stall = firstIndex(s, Sample::stalled);
        assertTrue(stall >= 0, "it drove into the wall and stalled");
        Sample atWall = s.get(stall);
        List<Sample> after = s.subList(stall, s.size());
        double minX = after.stream().mapToDouble(Sample::x).min().orElseThrow();
        // ARIA's sequence: back and turn, forward and turn, then back alone, each up to 50 cycles and
        // the next within 5 s of the last. Pressed flat against the wall, turning swings a front corner
        // into it, so the first two are blocked as in Stage; backing alone frees the robot
        assertTrue(atWall.x() - minX > 100, "backed off the wall by " + (atWall.x() - minX) + " mm");
        assertFalse(last(s).stalled(), "free of the wall again");
    }

    @Test
    void limiterForwardsStopsTheRobotShortOfAWallAtItsStopDistance() throws Exception {
        List<Sample> s = run(5000, 3000, 0, 40_000, robot -> {
            robot.addRangeDevice(new ArSonarDevice());
            robot.addAction(new ArActionLimiterForwards(), 90);
            robot.addAction(new ArActionConstantVelocity("go", 400), 25);
        });

        Sample end = last(s);
        assertTrue(s.stream().noneMatch(Sample::stalled), "it never touched the wall");
        assertEquals(0, end.vel(), 0.5, "stopped");
        // the limiter stops when the nearest echo, less half the robot's length, is under 250 mm:
        // an echo 250 + 511/2 = 505.5 mm from the centre, the front being 210 mm ahead of the centre;
        // the echoes of the ±10° sonars come up to ~7 mm beyond the wall's perpendicular distance
        double expected = 250 + LENGTH / 2 - FRONT;
        double gap = EAST_WALL - (end.x() + FRONT);
        assertTrue(gap <= expected + 2 && gap >= expected - 12,
                "front " + gap + " mm from the wall, expected " + expected + " less up to 12");
    }

    @Test
    void limiterBackwardsStopsTheRobotShortOfAWallBehindAtItsStopDistance() throws Exception {
        List<Sample> s = run(3000, 3000, 0, 40_000, robot -> {
            robot.addRangeDevice(new ArSonarDevice());
            robot.addAction(new ArActionLimiterBackwards(), 90);
            robot.addAction(new Backwards(300), 25);
        });

        Sample end = last(s);
        assertTrue(s.stream().noneMatch(Sample::stalled), "it never touched the wall");
        assertEquals(0, end.vel(), 0.5, "stopped");
        // it stops when the nearest echo behind, less the robot's radius (250), is under 250 mm: an
        // echo 500 mm from the centre, the rear being 301 mm behind it
        double expected = 250 + 250 - REAR;
        double gap = end.x() - REAR - WEST_WALL;
        assertTrue(gap <= expected + 2 && gap >= expected - 12,
                "rear " + gap + " mm from the wall, expected " + expected + " less up to 12");
    }

    @Test
    void ariasWanderBuiltFromActionsKeepsGoingWithoutHittingAnything() throws Exception {
        List<Sample> s = run(4000, 3000, 30, 60_000, ActionWander::addTo);

        double path = 0;
        for (int i = 1; i < s.size(); i++) {
            path += Math.hypot(s.get(i).x() - s.get(i - 1).x(), s.get(i).y() - s.get(i - 1).y());
        }
        assertTrue(path > 8000, "it wandered " + path + " mm in a minute");
        long stalledCycles = s.stream().filter(Sample::stalled).count();
        assertFalse(stalledCycles > 10, "stalled " + stalledCycles + " cycles");
    }

    private static <T> int firstIndex(List<T> list, java.util.function.Predicate<T> p) {
        for (int i = 0; i < list.size(); i++) {
            if (p.test(list.get(i))) {
                return i;
            }
        }
        return -1;
    }

    /** Wants to drive backwards at a constant speed. */
    private static final class Backwards extends ArAction {
        private final ArActionDesired desired = new ArActionDesired();
        private final double speed;

        Backwards(double speed) {
            super("backwards");
            this.speed = speed;
        }

        @Override
        public ArActionDesired fire(ArActionDesired currentDesired) {
            desired.reset();
            desired.setVel(-speed);
            return desired;
        }
    }
}
