package robosim.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.params.RobotParameterFiles;
import robosim.pioneer.Commands;
import robosim.pioneer.PioneerPacket;
import robosim.protocol.Command;
import robosim.protocol.RobotHello;
import robosim.protocol.SonarReading;
import robosim.protocol.Welcome;

/** A PioneerLink against a Pioneer server played by the test: the connect sequence, the steps, bye and loss. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class PioneerLinkTest {
    private static final RobotHello HELLO = new RobotHello("r1", "pioneer", RobotParameterFiles.load("p3dx"));

    /** Keeps what the link delivers. */
    static final class Receiver implements StepReceiver {
        final BlockingQueue<RobotSensorResponse> steps = new LinkedBlockingQueue<>();
        final BlockingQueue<String> ended = new LinkedBlockingQueue<>();

        @Override
        public void step(RobotSensorResponse response) {
            steps.add(response);
        }

        @Override
        public void ended(RunEnd.Kind kind, String reason) {
            ended.add(kind + ": " + reason);
        }
    }

    private static List<Integer> ids(FakePioneerServer server, int count) throws InterruptedException {
        List<Integer> ids = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            PioneerPacket p = server.received.poll(5, TimeUnit.SECONDS);
            assertNotNull(p, "packets so far: " + ids);
            if (p.id() != Commands.PULSE) {
                ids.add(p.id());
            } else {
                i--;
            }
        }
        return ids;
    }

    @Test
    void itOpensLeavesTheMotorsToTheProgramAndMakesEachSipAStep() throws Exception {
        try (FakePioneerServer server = new FakePioneerServer(5)) {
            PioneerLink link = EnvironmentLinks.pioneer("127.0.0.1:" + server.port(), HardwareOptions.defaults());
            Receiver receiver = new Receiver();
            Welcome w = link.open(HELLO, receiver);
            try {
                assertEquals(50, w.stepMs(), "the CONFIG reply's SIP cycle");
                assertEquals(java.util.Map.of(), w.properties(), "a robot server has no world");
                assertEquals(0, w.seed(), "a robot server has no run");
                assertEquals(List.of(Commands.OPEN, Commands.CONFIG), ids(server, 2));
                RobotSensorResponse first = receiver.steps.poll(5, TimeUnit.SECONDS);
                assertNotNull(first);
                assertEquals(Boolean.FALSE, first.state().motorsEnabled(), "the SIP's flags bit 0 is clear");
                link.send(1, List.of(new RobotRequest(new Command.SetMotors(true))));
                assertEquals(List.of(Commands.ENABLE), ids(server, 1), "enableMotors() sends ENABLE, as ARIA's does");
                assertEquals(1, first.step());
                assertEquals(10, first.state().x(), 1e-9, "p3dx-sh has no parameter file: a DistConvFactor of 1");
                assertEquals(700, first.state().get(SonarReading.PART).ranges()[3]);
            } finally {
                link.close();
            }
        }
    }

    @Test
    void byeDisablesTheMotorsAndCloses() throws Exception {
        try (FakePioneerServer server = new FakePioneerServer(1)) {
            PioneerLink link = EnvironmentLinks.pioneer("127.0.0.1:" + server.port(), HardwareOptions.defaults());
            link.open(HELLO, new Receiver());
            ids(server, 2);
            link.send(1, List.of(new RobotRequest(new Command.SetVel(100))));
            link.bye("done");
            assertEquals(List.of(Commands.VEL, Commands.ENABLE, Commands.CLOSE), ids(server, 3));
        }
    }

    @Test
    void aServerThatFallsSilentIsLost() throws Exception {
        try (FakePioneerServer server = new FakePioneerServer(2)) {
            PioneerLink link = EnvironmentLinks.pioneer("127.0.0.1:" + server.port(), new HardwareOptions(5_000, 400, 5_000));
            Receiver receiver = new Receiver();
            link.open(HELLO, receiver);
            String ended = receiver.ended.poll(5, TimeUnit.SECONDS);
            assertEquals("LOST: it sent no status packet for 400 ms", ended);
            assertEquals(1, receiver.steps.size(), "the first SIP made the welcome, the second one step");
        }
    }
}
