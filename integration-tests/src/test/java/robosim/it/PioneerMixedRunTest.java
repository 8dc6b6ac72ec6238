package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.cli.Background;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;
import robosim.examples.scoutwander.ScoutWander;
import robosim.examples.wander.Wander;
import robosim.pioneer.Commands;
import robosim.pioneer.PioneerClient;
import robosim.pioneer.Sip;

/** A Java ArRobot program, a Scout program and a Pioneer-protocol client drive the robots of one run. */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class PioneerMixedRunTest {
    static final int STEPS = 60;

    @Test
    void aJavaRobotAScoutAndAnAriaClientShareOneRun() throws Exception {
        try (PioneerRun run = new PioneerRun(LocalEnvironment.shipped("mixed-team.xml"), STEPS, false, code -> { })) {
            String port = Integer.toString(run.env.robotPort());
            CompletableFuture<Void> scout = Background.supply("s1", () -> {
                ScoutWander.main(new String[] {"s1", "127.0.0.1", port});
                return null;
            });
            CompletableFuture<Void> pioneer = Background.supply("r1", () -> {
                Wander.main(new String[] {"r1", "127.0.0.1", port});
                return null;
            });
            Sip last;
            int sips = 0;
            try (PioneerClient c = run.client("r2")) {
                c.send(Commands.comInt(Commands.ENABLE, 1));
                c.send(Commands.comInt(Commands.VEL, 200));
                Sip s;
                last = null;
                while ((s = c.nextSip(3000)) != null) {
                    last = s;
                    sips++;
                }
                assertTrue(c.isClosed(), "the port closes when the run ends");
            }
            RunReport report = run.env.await(60);
            scout.get(30, TimeUnit.SECONDS);
            pioneer.get(30, TimeUnit.SECONDS);
            assertEquals(STEPS, report.steps());
            for (RobotSummary r : report.robots()) {
                assertTrue(r.distance() > 100, r.name() + " moved: " + r.distance());
            }
            assertNotNull(last);
            assertTrue(sips >= STEPS - 5, "a SIP each step: " + sips);
            RobotSummary r2 = report.robots().stream().filter(r -> r.name().equals("r2")).findFirst().orElseThrow();
            assertEquals(r2.distance(), last.xPos() * 0.485, 60, "the client's odometry follows r2");
        }
    }
}
