package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArRobot;
import robosim.cli.Background;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;

/** ARIA's everyday names on a live Environment: a limit set reaches the drive, the odometer adds up, disconnect answers as ARIA's. */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class AriaNamesEndToEndTest {
    @TempDir
    Path dir;

    /** What the program saw. */
    private record Seen(double velAfterOneSecond, double odometer, double straightLine, boolean first, boolean second) { }

    @Test
    void anAccelerationSetReachesTheDriveAndTheOdometerAddsTheWay() throws Exception {
        Path world = dir.resolve("room.xml");
        Files.writeString(world, """
                <world name="room" width="8000" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="1000" y="3000" th="0" params="%s"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.xml")));
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world), 7, ServerOptions.loopback())) {
            CompletableFuture<Seen> seen = Background.supply("robot r1", () -> {
                ArRobot robot = new ArRobot("r1", "127.0.0.1", env.robotPort(), "p3dx.xml");
                if (!robot.blocking_connect()) {
                    throw new IllegalStateException(robot.getConnectionError());
                }
                robot.enableMotors();
                double x0 = robot.getX();
                double y0 = robot.getY();
                robot.setTransAccel(100);
                robot.setTransAccel(0); // ignored, as in ARIA: the 100 stays
                robot.setVel(300);
                robot.sleepSimulated(1000);
                double vel = robot.getVel();
                robot.sleepSimulated(1000);
                double odometer = robot.getOdometerDistance();
                double line = Math.hypot(robot.getX() - x0, robot.getY() - y0);
                boolean first = robot.disconnect();
                boolean second = robot.disconnect();
                return new Seen(vel, odometer, line, first, second);
            });
            Seen s = seen.get(60, TimeUnit.SECONDS);
            env.await(60);

            // 100 mm/s² for about a second from rest: about 100 mm/s, far from the 300 asked for
            assertEquals(100, s.velAfterOneSecond(), 15);
            // driving straight ahead, the odometer is the straight line travelled
            assertTrue(s.odometer() > 100, "it drove: " + s.odometer());
            assertEquals(s.straightLine(), s.odometer(), 1);
            assertTrue(s.first(), "the first disconnect left the run");
            assertTrue(s.second(), "the second found nothing to close, which ARIA's disconnect answers true (ArRobot.cpp)");
        }
    }

    /** The odometers after a program drove a 1 m square. */
    private record Square(double distance, double degrees, double tripDistance, double tripDegrees) { }

    @Test
    void afterAOneMetreSquareTheOdometerSaysFourMetresAndAFullTurnAndTheTripHalfThat() throws Exception {
        Path world = dir.resolve("square.xml");
        Files.writeString(world, """
                <world name="square" width="8000" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="3000" y="2000" th="0" params="%s"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.xml")));
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world), 7, ServerOptions.loopback())) {
            CompletableFuture<Square> seen = Background.supply("robot r1", () -> {
                ArRobot robot = ActionPrograms.connect(env, "r1");
                double tripDistance = 0;
                double tripDegrees = 0;
                for (int side = 0; side < 4; side++) {
                    if (side == 2) {
                        robot.resetTripOdometer();
                    }
                    robot.move(1000);
                    settle(robot);
                    robot.setDeltaHeading(90);
                    settle(robot);
                }
                tripDistance = robot.getTripOdometerDistance();
                tripDegrees = robot.getTripOdometerDegrees();
                Square s = new Square(robot.getOdometerDistance(), robot.getOdometerDegrees(), tripDistance, tripDegrees);
                robot.disconnect();
                return s;
            });
            Square s = seen.get(60, TimeUnit.SECONDS);
            env.await(60);

            // each move ends on its mark and each turn on its heading (no noise): 4 m and 360°
            assertEquals(4000, s.distance(), 2);
            assertEquals(360, s.degrees(), 1);
            assertEquals(2000, s.tripDistance(), 2);
            assertEquals(180, s.tripDegrees(), 1);
        }
    }

    /** Waits until the last motion command is done and the robot has stopped. */
    private static void settle(ArRobot robot) {
        do {
            robot.sleepSimulated(100);
        } while (!(robot.isMoveDone(0.5) && robot.isHeadingDone(0.1) && robot.isStopped(0.5, 0.1)));
    }
}
