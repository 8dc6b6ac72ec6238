package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArRobot;
import robosim.aria.ArUtil;
import robosim.cli.Background;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunEnding;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.hw.RunEnd;
import robosim.protocol.Snapshot;
import robosim.protocol.recording.Recording;
import robosim.protocol.recording.RecordingReader;
import robosim.protocol.recording.RecordingWriter;
import robosim.scout.Scout;
import robosim.viewer.replay.RecordingSummary;

/**
 * Robot programs over TCP report metrics and one ends the run: a Pioneer counts the 500 mm cells it
 * drives through and ends the run when it has seen six, a Scout counts the states it read. The run's
 * report and its recording hold what they reported and the request that ended it.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class RunMetricsEndToEndTest {
    private static final int CELL_MM = 500;
    private static final int CELLS_WANTED = 6;

    @TempDir
    Path dir;

    /** What the Pioneer's program knew when it asked to end the run. */
    record Explorer(long askedInStep, int cells, RunEnd.Kind end) { }

    /** Drives ahead, reporting the cells explored, until it has explored enough; then ends the run. */
    private static Explorer explore(int port) {
        ArRobot robot = new ArRobot("r1", "127.0.0.1", port, "p3dx");
        if (!robot.blockingConnect()) {
            throw new IllegalStateException(robot.getConnectionError());
        }
        robot.enableMotors();
        robot.broadcast("exploring");
        robot.setVel(400);
        Set<Long> cells = new HashSet<>();
        while (cells.size() < CELLS_WANTED) {
            ArUtil.sleep(100);
            if (cells.add(Math.floorDiv((long) robot.getX(), CELL_MM))) {
                robot.reportMetric("cellsExplored", cells.size());
            }
        }
        // the requests made now go with the robot's requests for the step after the state it holds
        long step = robot.getStep() + 1;
        robot.reportMetric("stepFound", step);
        robot.endRun("explored " + CELLS_WANTED + " cells");
        robot.waitForRunExit();
        return new Explorer(step, cells.size(), robot.getRunEnd().kind());
    }

    /** Counts the states it reads until the run ends. */
    private static Long watch(int port) {
        Scout scout = new Scout("s1", "127.0.0.1", port);
        if (!scout.connect_robot()) {
            throw new IllegalStateException(scout.getConnectionError());
        }
        long seen = 0;
        while (scout.gs()) {
            seen++;
            scout.report_metric("scout.statesSeen", seen);
        }
        return seen;
    }

    @Test
    void theReportAndTheRecordingHoldTheMetricsAndTheRequestThatEndedTheRun() throws Exception {
        Path world = ThreadedRun.world(dir, "hall.xml", """
                <world name="hall" width="8000" height="4000" boundary="true">
                  <robot name="r1" type="pioneer" x="1200" y="1000" th="0" params="%ROBOTS%/p3dx.p"/>
                  <robot name="s1" type="scout" x="1200" y="3000" th="0" params="%ROBOTS%/scout.p"/>
                </world>
                """);
        Path recording = dir.resolve("hall.rsr");
        RunReport report;
        Explorer explorer;
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world), 1,
                ServerOptions.loopback().withMaxSteps(400), RecordingWriter.create(recording, false))) {
            CompletableFuture<Explorer> r1 = Background.supply("robot r1", () -> explore(env.robotPort()));
            CompletableFuture<Long> s1 = Background.supply("robot s1", () -> watch(env.robotPort()));
            report = env.await(90);
            explorer = r1.get(30, TimeUnit.SECONDS);
            assertTrue(s1.get(30, TimeUnit.SECONDS) > 0);
        }

        long step = explorer.askedInStep();
        String reason = "ended by robot r1 at step " + step + ": explored 6 cells";
        assertEquals(RunEnding.ROBOT_ENDED, report.ending());
        assertEquals(reason, report.endReason());
        assertEquals(new Snapshot.EndRequest("r1", step, "explored 6 cells"), report.endRequest());
        assertEquals(step, report.steps(), "the run ends after the step the request came in");
        assertEquals(RunEnd.Kind.RUN_ENDED, explorer.end());
        assertEquals(List.of("r1", "s1"), List.copyOf(report.metrics().keySet()));
        assertEquals(Map.of("cellsExplored", 6.0, "stepFound", (double) step), report.metrics().get("r1"));
        assertEquals(List.of("cellsExplored", "stepFound"), List.copyOf(report.metrics().get("r1").keySet()));
        double statesSeen = report.metrics().get("s1").get("scout.statesSeen");
        assertTrue(statesSeen >= step - 2 && statesSeen <= step, "the Scout read a state every step: " + statesSeen);
        RobotSummary r1 = report.robots().get(0);
        RobotSummary s1 = report.robots().get(1);
        assertEquals(1, r1.messagesSent());
        assertEquals(0, r1.messagesLost());
        assertEquals(1, s1.messagesReceived());
        assertEquals(0, r1.stalls(), "nothing stood in r1's way");

        try (RecordingReader reader = RecordingReader.open(recording)) {
            RecordingSummary summary = RecordingSummary.of(reader);
            assertEquals(report.metrics(), summary.metrics());
            assertEquals(report.endRequest(), summary.endRequest());
            assertEquals("done: " + reason, summary.endReason());
            assertEquals(step, summary.lastStep());
        }
        Recording whole = Recording.read(recording);
        Snapshot last = whole.snapshots().get(whole.snapshots().size() - 1).snapshot();
        assertEquals(report.endRequest(), last.endRequest(), "the last step's snapshot carries the request");
        assertTrue(last.metrics().contains(new Snapshot.Metric("r1", "stepFound", step)), last.metrics().toString());
        assertNull(whole.snapshots().get(1).snapshot().endRequest());
    }
}
