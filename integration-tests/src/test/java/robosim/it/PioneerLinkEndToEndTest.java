package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArPose;
import robosim.aria.ArRobot;
import robosim.aria.ArSonarDevice;
import robosim.aria.ArUtil;
import robosim.cli.Background;
import robosim.env.core.RobotSummary;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.hw.HardwareOptions;
import robosim.hw.RobotRuntime;
import robosim.hw.RuntimeChoices;
import robosim.params.ConversionFactors;
import robosim.params.RobotParameterFiles;
import robosim.pioneer.server.PioneerPortOptions;
import robosim.pioneer.server.PioneerPorts;
import robosim.pioneer.server.ServedRobot;

/**
 * The same ArRobot program, unchanged, drives a robot once through the Environment's own protocol
 * and once through the Pioneer protocol (RoboSim's own Pioneer port, as it would drive MobileSim),
 * and ends where ARIA's motion allows in both.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class PioneerLinkEndToEndTest {
    /** A p3dx's factors, as its parameter file gives them. */
    private static final ConversionFactors P3DX = new ConversionFactors(0.001534, 0.485, 1, 1, 0.0056, 20);

    @TempDir
    Path dir;

    /**
     * Where the program ended, from where it started, and what its front sonar read there; its
     * battery standing at the start and at speed.
     */
    record Drive(double dx, double dy, double th, int frontSonar, int sonarBuffer, double batteryStanding,
                 double batteryDriving) { }

    @Test
    void theSameProgramEndsAtTheSamePoseThroughTheEnvironmentAndThroughAPioneerServer() throws Exception {
        Path world = world();
        Drive direct;
        RobotSummary directTruth;
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world), 1, ServerOptions.loopback())) {
            int port = env.robotPort();
            RobotRuntime runtime = RobotRuntime.create("direct", RuntimeChoices.defaults());
            direct = Background.supply("robot r1", () -> drive(port, runtime)).get(60, TimeUnit.SECONDS);
            env.await(30);
            directTruth = env.sim.summary("r1");
        }

        Drive pioneer;
        RobotSummary pioneerTruth;
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world), 1, ServerOptions.loopback());
             PioneerPorts ports = PioneerPorts.open(
                     List.of(new ServedRobot("r1", "pioneer", RobotParameterFiles.load("p3dx"), P3DX, 100)),
                     new PioneerPortOptions("127.0.0.1", 0, false, 2000, true, HardwareOptions.defaults()),
                     "127.0.0.1", env.robotPort(), null, code -> { })) {
            int port = ports.portOf("r1");
            // the program's robot reaches the Environment through the Pioneer port, as robosim.pioneer says
            RobotRuntime runtime = RobotRuntime.create("pioneer",
                    RuntimeChoices.defaults().withPioneer("127.0.0.1:" + port));
            pioneer = Background.supply("robot r1", () -> drive(port, runtime)).get(60, TimeUnit.SECONDS);
            pioneerTruth = env.sim.summary("r1");
        }

        assertEquals(1000, direct.dx(), 50, "the Environment's run drove 1 m ahead: " + direct);
        assertEquals(500, direct.dy(), 50, "then 0.5 m to the left: " + direct);
        assertEquals(direct.dx(), pioneer.dx(), 50, "odometry x: " + direct + " / " + pioneer);
        assertEquals(direct.dy(), pioneer.dy(), 50, "odometry y: " + direct + " / " + pioneer);
        assertEquals(90, pioneer.th(), 3, "heading through the Pioneer server: " + pioneer);
        assertEquals(directTruth.x(), pioneerTruth.x(), 50, "true x: " + directTruth + " / " + pioneerTruth);
        assertEquals(directTruth.y(), pioneerTruth.y(), 50, "true y: " + directTruth + " / " + pioneerTruth);
        assertEquals(directTruth.th(), pioneerTruth.th(), 3, "true heading");
        // the front sonars (10° off the heading, 166 mm ahead) see the wall at y = 5900 from y = 3500
        int expected = (int) Math.round((5900 - 3500 - 166) / Math.cos(Math.toRadians(10)));
        assertEquals(expected, direct.frontSonar(), 60, "the Environment's sonar: " + direct);
        assertEquals(direct.frontSonar(), pioneer.frontSonar(), 60, "the sonar through the Pioneer server: " + pioneer);
        assertTrue(pioneer.sonarBuffer() > 0, "the sonar device took readings through the Pioneer server");
        assertEquals(12.9, direct.batteryStanding(), 0.001, "a full battery, the electronics' 1 A sagging it");
        assertEquals(12.9, pioneer.batteryStanding(), 1e-9, "the same in the SIP's decivolts");
        assertTrue(direct.batteryDriving() < 12.85, "the motors' current sags it: " + direct);
        assertEquals(direct.batteryDriving(), pioneer.batteryDriving(), 0.051, "through the SIP: " + pioneer);
    }

    private Path world() throws Exception {
        Path world = dir.resolve("room.xml");
        Files.writeString(world, """
                <world name="room" width="6000" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="2500" y="3000" th="0" params="%s"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p")));
        return world;
    }

    /** The program: 1 m ahead, turn to heading 90, 0.5 m on, then read the front sonar. Unchanged for both links. */
    private static Drive drive(int port, RobotRuntime runtime) {
        ArRobot robot = new ArRobot("r1", "127.0.0.1", port, "p3dx");
        robot.setRuntime(runtime);
        ArSonarDevice sonar = new ArSonarDevice();
        robot.addRangeDevice(sonar);
        if (!robot.blockingConnect()) {
            throw new IllegalStateException(robot.getConnectionError());
        }
        robot.enableMotors();
        ArUtil.sleep(300);
        ArPose start = robot.getPose();
        double standing = robot.getBatteryVoltageNow();
        robot.move(1000);
        waitFor(robot, () -> robot.getVel() > 400);
        double driving = robot.getBatteryVoltageNow();
        waitFor(robot, () -> robot.isMoveDone());
        robot.setHeading(90);
        waitFor(robot, () -> robot.isHeadingDone());
        robot.move(500);
        waitFor(robot, () -> robot.isMoveDone());
        waitFor(robot, robot::isStopped);
        ArUtil.sleep(500);
        ArPose end = robot.getPose();
        Drive d = new Drive(end.getX() - start.getX(), end.getY() - start.getY(), end.getTh(),
                Math.min(robot.getSonarRange(3), robot.getSonarRange(4)), sonar.getCurrentBuffer().size(), standing,
                driving);
        robot.disconnect();
        return d;
    }

    /** Waits, in the robot's time, at most 30 s of it. */
    private static void waitFor(ArRobot robot, java.util.function.BooleanSupplier done) {
        for (int i = 0; i < 300 && robot.isConnected() && !done.getAsBoolean(); i++) {
            ArUtil.sleep(100);
        }
        if (!done.getAsBoolean()) {
            throw new IllegalStateException("robot r1 did not get there: " + robot.getPose() + ", "
                    + robot.getRunEnd());
        }
    }
}
