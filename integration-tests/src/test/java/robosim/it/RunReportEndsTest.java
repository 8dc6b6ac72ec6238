package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArRobot;
import robosim.env.net.Departure;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.examples.wander.Wander;
import robosim.params.ParameterFileReader;
import robosim.protocol.Bye;
import robosim.protocol.KeepAlive;
import robosim.protocol.Message;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotParameters;
import robosim.protocol.RobotRequests;
import robosim.protocol.TimeStep;
import robosim.protocol.Welcome;

/**
 * The run report marks each robot that left, was dropped or was lost, with the step and the reason,
 * next to the robots that ran to the end; and robots that wait legitimately hear the Environment's
 * keep-alive.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class RunReportEndsTest {
    private static final int STEPS = 30;

    @TempDir
    Path dir;

    private static RobotParameters p3dx() {
        return ParameterFileReader.read(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p"));
    }

    /**
     * Says hello as each robot of {@code peers}, answers step 1 for them and for {@code welcomed}
     * (robots already welcomed) with nothing, and reads step 2 as it opens, if the run goes on.
     */
    private static void joinAndAnswerStep1(List<RawPeer> peers, List<String> names, RawPeer... welcomed)
            throws IOException {
        for (int i = 0; i < peers.size(); i++) {
            peers.get(i).send(new RobotHello(names.get(i), "pioneer", p3dx()));
        }
        for (RawPeer peer : peers) {
            assertInstanceOf(Welcome.class, nextStepOrWelcome(peer));
        }
        List<RawPeer> all = new java.util.ArrayList<>(peers);
        all.addAll(List.of(welcomed));
        for (RawPeer peer : all) {
            TimeStep first = assertInstanceOf(TimeStep.class, nextStepOrWelcome(peer));
            peer.send(new RobotRequests(first.step(), List.of()));
        }
        for (RawPeer peer : all) {
            Message next = nextStepOrWelcome(peer);
            if (!(next instanceof Bye)) {
                assertEquals(2, assertInstanceOf(TimeStep.class, next).step());
            }
        }
    }

    /** @return the next message that is not a keep-alive */
    private static Message nextStepOrWelcome(RawPeer peer) throws IOException {
        Message m;
        do {
            m = peer.read();
        } while (m instanceof KeepAlive);
        return m;
    }

    @Test
    void theLostRobotIsMarkedInTheReportAsAreTheOnesThatLeftOrWereDropped() throws Exception {
        Path p3dx = LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p").toAbsolutePath();
        Path world = dir.resolve("four-robots.xml");
        Files.writeString(world, """
                <?xml version="1.0" encoding="UTF-8"?>
                <world name="four-robots" width="8000" height="8000" boundary="true">
                  <robot name="r1" type="pioneer" x="1500" y="1500" params="%1$s"/>
                  <robot name="r2" type="pioneer" x="6500" y="1500" params="%1$s"/>
                  <robot name="r3" type="pioneer" x="1500" y="6500" params="%1$s"/>
                  <robot name="r4" type="pioneer" x="6500" y="6500" params="%1$s"/>
                </world>
                """.formatted(p3dx));
        // r4 stops answering in its second step: no first steps' allowance here
        ServerOptions options = new ServerOptions("127.0.0.1", 0, 0, STEPS, false, 500, 30_000, 0, 4 << 20)
                .withFirstStepsTimeoutMs(500);
        try (LocalEnvironment h = new LocalEnvironment(WorldReader.read(world), 1, options);
             RawPeer r2 = new RawPeer(h.robotPort());
             RawPeer r3 = new RawPeer(h.robotPort());
             RawPeer r4 = new RawPeer(h.robotPort())) {
            Thread r1 = new Thread(() -> {
                ArRobot robot = new ArRobot("r1", "127.0.0.1", h.robotPort(), "p3dx");
                if (robot.blockingConnect()) {
                    robot.enableMotors();
                    new Wander(robot).run();
                }
            }, "robot-r1");
            r1.setDaemon(true);
            r1.start();
            joinAndAnswerStep1(List.of(r2, r3, r4), List.of("r2", "r3", "r4"));

            r2.send(new Bye("its work is done"));
            r3.close(); // gone without a bye, as a robot program that died
            // r4 says nothing: it misses step 2's deadline
            assertEquals(new Bye("it did not send its requests for step 2 within 500 ms (env --step-timeout gives it longer)"),
                    nextStepOrWelcome(r4));

            RunReport report = h.await();
            assertEquals("step limit " + STEPS + " reached", report.endReason());
            assertEquals(Optional.empty(), report.departure("r1"), "r1 ran to the end");
            assertEquals(Optional.of(new Departure("r2", Departure.Kind.LEFT, 2, "its work is done")),
                    report.departure("r2"));
            assertEquals(Optional.of(new Departure("r3", Departure.Kind.LOST, 2, "the connection closed without a bye")),
                    report.departure("r3"));
            assertEquals(Optional.of(new Departure("r4", Departure.Kind.DROPPED, 2,
                    "it did not send its requests for step 2 within 500 ms (env --step-timeout gives it longer)")),
                    report.departure("r4"));
            assertEquals(3, report.departures().size(), report.departures().toString());
            r1.join(10_000);
        }
    }

    @Test
    void aRobotWaitingForTheOthersToConnectHearsKeepAlivesMeanwhile() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback().withMaxSteps(1));
             RawPeer r1 = new RawPeer(h.robotPort());
             RawPeer r2 = new RawPeer(h.robotPort())) {
            r1.send(new RobotHello("r1", "pioneer", p3dx()));
            assertInstanceOf(Welcome.class, r1.read());

            // r2 has not connected: the run waits, and says so again and again (each read waits at most 20 s)
            assertEquals(new KeepAlive(0), r1.read());
            assertEquals(new KeepAlive(0), r1.read());

            // then r2 comes, and the run of one step is run and ended (not cut off by closing the server)
            joinAndAnswerStep1(List.of(r2), List.of("r2"), r1);
            assertEquals("step limit 1 reached", h.await().endReason());
        }
    }
}
