package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArGripper;
import robosim.aria.ArRobot;
import robosim.cli.Background;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.Snapshot;

/**
 * A Pioneer with a gripper, programmed through ARIA's ArGripper on a live Environment: it drives
 * to a puck until a break beam breaks, closes the paddles on it, lifts it, carries it 2 m, lowers
 * and opens, and backs away; the puck lies where the gripper put it down.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class GripperEndToEndTest {
    @TempDir
    Path dir;

    /** What the program saw through ArGripper. */
    private record Seen(ArGripper.Type type, int beamsAtStop, int gripWhenHeld, int paddlesWhenHeld,
                        boolean liftMaxedWhenUp, int gripWhenOpened, double carriedOdometry) { }

    /** Sleeps a simulated cycle at a time until the test holds, at most {@code steps} cycles. */
    private static void until(ArRobot robot, int steps, String what, BooleanSupplier done) {
        for (int i = 0; i < steps; i++) {
            if (done.getAsBoolean()) {
                return;
            }
            robot.sleepSimulated(100);
        }
        throw new IllegalStateException("robot " + robot.getName() + ": not " + what + " in " + steps + " cycles");
    }

    private static Seen program(int port) {
        ArRobot robot = new ArRobot("r1", "127.0.0.1", port, "p3dx-gripper");
        if (!robot.blocking_connect()) {
            throw new IllegalStateException(robot.getConnectionError());
        }
        robot.enableMotors();
        ArGripper gripper = new ArGripper(robot);
        robot.sleepSimulated(100);
        ArGripper.Type type = gripper.getType();
        gripper.gripperDeploy();
        robot.setVel(150);
        until(robot, 200, "at the puck", () -> gripper.getBreakBeamState() != 0);
        robot.stop();
        int beams = gripper.getBreakBeamState();
        gripper.gripClose();
        robot.sleepSimulated(200);
        until(robot, 60, "holding", () -> gripper.getGripState() == 2 && !gripper.isGripMoving());
        int grip = gripper.getGripState();
        int paddles = gripper.getPaddleState();
        gripper.liftUp();
        robot.sleepSimulated(200);
        until(robot, 60, "lifted", () -> gripper.isLiftMaxed() && !gripper.isLiftMoving());
        boolean maxed = gripper.isLiftMaxed();
        double x0 = robot.getX();
        robot.move(2000);
        robot.sleepSimulated(200);
        until(robot, 300, "carried", () -> robot.isMoveDone(0.5) && robot.getVel() == 0);
        double carried = robot.getX() - x0;
        gripper.liftDown();
        robot.sleepSimulated(200);
        until(robot, 60, "lowered", () -> gripper.isLiftMaxed() && !gripper.isLiftMoving());
        gripper.gripOpen();
        robot.sleepSimulated(200);
        until(robot, 60, "open", () -> gripper.getGripState() == 1);
        int opened = gripper.getGripState();
        robot.move(-500);
        robot.sleepSimulated(200);
        until(robot, 100, "backed away", () -> robot.isMoveDone(0.5) && robot.getVel() == 0);
        robot.disconnect();
        return new Seen(type, beams, grip, paddles, maxed, opened, carried);
    }

    @Test
    void aRobotCarriesAPuckTwoMetresAndPutsItDownWhereItsGripperWas() throws Exception {
        Path world = dir.resolve("pucks.xml");
        Files.writeString(world, """
                <world name="pucks" width="8000" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="1000" y="3000" th="0" params="%s"/>
                  <object type="puck" x="2000" y="3000" color="red"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx-gripper.p")));
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world), 7, ServerOptions.loopback())) {
            SnapshotCollector viewer = new SnapshotCollector(env.viewerPort());
            CompletableFuture<Seen> seen = Background.supply("robot r1", () -> program(env.robotPort()));
            Seen s = seen.get(90, TimeUnit.SECONDS);
            env.await(60);
            List<Snapshot> frames = viewer.snapshots();

            assertEquals(ArGripper.Type.GENIO, s.type(), "the query answered: a gripper on the general IO");
            assertTrue(s.beamsAtStop() != 0, "a beam broke");
            assertEquals(2, s.gripWhenHeld(), "ARIA's closed: both paddles triggered");
            assertEquals(3, s.paddlesWhenHeld());
            assertTrue(s.liftMaxedWhenUp());
            assertEquals(1, s.gripWhenOpened());
            assertEquals(2000, s.carriedOdometry(), 1, "the Move ends within 1 mm of its 2000");

            Snapshot lastHeld = null;
            Snapshot firstHeld = null;
            Snapshot dropped = null;
            for (Snapshot f : frames) {
                Snapshot.ObjectView p = f.objects().get(0);
                if (p.heldBy() != null) {
                    firstHeld = firstHeld == null ? f : firstHeld;
                    lastHeld = f;
                } else if (lastHeld != null && dropped == null) {
                    dropped = f;
                }
            }
            assertNotNull(dropped, "the puck was held and put down");
            Snapshot.ObjectView atGrip = firstHeld.objects().get(0);
            Snapshot.RobotView gripper = firstHeld.robots().get(0);
            // held centred ahead of the body (the p3dx reaches 210 mm ahead; a puck is 38 mm in radius),
            // within the paddles' 180 mm reach
            double ahead = atGrip.x() - gripper.x();
            assertTrue(ahead >= 210 + 38 && ahead <= 210 + 180, "held " + ahead + " mm ahead of the centre");
            assertEquals(3000, atGrip.y(), 1e-6);
            // put down where the gripper was when the paddles opened: that same offset ahead of the robot
            Snapshot.RobotView atDrop = dropped.robots().get(0);
            Snapshot.ObjectView put = dropped.objects().get(0);
            assertEquals(atDrop.x() + ahead, put.x(), 1e-6);
            assertEquals(3000, put.y(), 1e-6);
            // carried 2 m: the robot's Move, within its 1 mm
            assertEquals(2000, put.x() - atGrip.x(), 1 + 1e-6);
            // and it stays there while the robot backs away
            Snapshot.ObjectView last = frames.get(frames.size() - 1).objects().get(0);
            assertNull(last.heldBy());
            assertEquals(put.x(), last.x(), 1e-9);
            assertTrue(frames.get(frames.size() - 1).robots().get(0).x() < atDrop.x() - 400, "it backed away");
        }
    }
}
