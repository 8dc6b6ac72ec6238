package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArHeatSensor;
import robosim.aria.ArRobot;
import robosim.aria.ArSick;
import robosim.aria.ArSonarDevice;
import robosim.aria.ArUtil;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.cli.Background;

/** The whole Pioneer interface over TCP: range devices, the laser, heat, backing into a wall, noise. */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class SensorsEndToEndTest {
    @TempDir
    Path dir;

    /** What the robot program saw. */
    record Seen(int laserAhead, int scanLength, double heat, double bearing, int sonarBuffer, boolean stalled,
                int rearSonar, int cycles, long counter) { }

    @Test
    void aPioneerProgramUsesEverySensorOverTcp() throws Exception {
        Path world = dir.resolve("room.xml");
        Files.writeString(world, """
                <world name="room" width="6000" height="6000" boundary="true">
                  <heat x="4500" y="3000" intensity="90"/>
                  <noise sonar="5" laser="5" odometry="0.0075"/>
                  <robot name="r1" type="pioneer" x="2500" y="3000" th="0" params="%s"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.xml")));
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world), 7, ServerOptions.loopback())) {
            CompletableFuture<Seen> seen = Background.supply("robot r1", () -> drive(env.robotPort()));
            Seen s = seen.get(60, TimeUnit.SECONDS);
            RunReport report = env.await(60);

            // the laser, 18 mm ahead of the centre, sees the boundary wall's face at x = 5900
            assertEquals(5900 - 2500 - 18, s.laserAhead(), 25);
            assertEquals(181, s.scanLength());
            // 90 at 1 m felt 2 m away: 22.5, straight ahead
            assertEquals(22.5, s.heat(), 0.5);
            assertEquals(0, s.bearing(), 1);
            assertTrue(s.sonarBuffer() > 0, "the sonar device took readings");
            assertTrue(s.stalled(), "backing up ended against the wall behind");
            assertEquals(100, s.rearSonar(), 20, "the rear sonars read the wall at contact");
            assertEquals(s.cycles(), s.counter(), "the user task ran once per cycle");
            RobotSummary r = report.robots().get(0);
            assertEquals(100 + 301, r.x(), 1, "the rear stopped at the wall's face (x = 100)");
            assertFalse(r.x() == r.odoX() && r.y() == r.odoY(), "odometry drifted from the true pose");
        }
    }

    private static Seen drive(int port) {
        ArRobot robot = new ArRobot("r1", "127.0.0.1", port, "p3dx.xml");
        ArSonarDevice sonar = new ArSonarDevice();
        ArSick laser = new ArSick();
        ArHeatSensor heat = new ArHeatSensor(90, 6000);
        robot.addRangeDevice(sonar);
        robot.addRangeDevice(laser);
        if (!robot.blockingConnect()) {
            throw new IllegalStateException(robot.getConnectionError());
        }
        robot.enableMotors();
        AtomicInteger cycles = new AtomicInteger();
        robot.addUserTask("count", 0, cycles::incrementAndGet);
        laser.blockingConnect();
        heat.attach(robot);
        ArUtil.sleep(300);
        int ahead = laser.getRawScan()[90];
        int length = laser.getRawScan().length;
        double felt = heat.getIntensity();
        double bearing = heat.getBearing();
        robot.move(-4000);
        while (!robot.isStalled() && robot.isConnected()) {
            ArUtil.sleep(100);
        }
        ArUtil.sleep(100);
        Seen s = new Seen(ahead, length, felt, bearing, sonar.getCurrentBuffer().size(), robot.isStalled(),
                Math.min(robot.getSonarRange(11), robot.getSonarRange(12)), cycles.get(), robot.getCounter());
        robot.disconnect();
        return s;
    }
}
