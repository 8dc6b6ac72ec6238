package robosim.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robosim.protocol.Bumpers;
import robosim.protocol.HeatReading;
import robosim.protocol.LaserReading;
import robosim.protocol.RobotState;
import robosim.protocol.SonarReading;
import robosim.protocol.StateParts;
import robosim.protocol.TruePose;

/** RobotUtil: message levels, the robot's name and step on each line, and the state's snapshot. */
class RobotUtilTest {
    private final TestRobot robot = new TestRobot("r1", 1);
    private final List<String> lines = new ArrayList<>();
    private RobotUtil out;

    @BeforeEach
    void toAList() {
        out = new RobotUtil(robot);
        out.setOutput(lines::add);
    }

    private void arrive(RobotState s) {
        robot.responded(new RobotSensorResponse(s));
    }

    @Test
    void eachLineCarriesTheNameTheStepAndTheTime() {
        arrive(new RobotState(42, 4200, 0, 0, 0, 0, 0, 0, 0, false, 0));
        assertTrue(out.normal("wall at %d mm", 750));
        assertEquals(List.of("[r1 step 42 4.200 s] NORMAL: wall at 750 mm"), lines);
    }

    @Test
    void beforeAnyStateTheStepIsZero() {
        out.terse("starting");
        assertEquals(List.of("[r1 step 0 0.000 s] TERSE: starting"), lines);
    }

    @Test
    void messagesMoreDetailedThanTheLevelAreDropped() {
        assertFalse(out.verbose("details"));
        out.setLevel(RobotUtil.Level.TERSE);
        assertFalse(out.normal("progress"));
        assertTrue(out.terse("result"));
        out.setLevel(RobotUtil.Level.VERBOSE);
        assertTrue(out.verbose("details"));
        assertEquals(2, lines.size());
    }

    @Test
    void aTextWithoutArgumentsIsNotFormatted() {
        out.normal("100% done");
        assertEquals("[r1 step 0 0.000 s] NORMAL: 100% done", lines.get(0));
    }

    @Test
    void theSnapshotPrintsEveryPartOfTheState() {
        RobotState s = new RobotState(7, 700, 1234.5, -678.25, 179.5, 350, -12.5, 337.5, 362.5, true, 3,
                List.of(), List.of("message 3 is addressed to 'nobody'"), null, StateParts.NONE)
                .with(SonarReading.PART, new SonarReading(new int[] {5000, 742, 650}, 0b101L))
                .with(LaserReading.PART, new LaserReading(new int[] {8000, 1234, 20, 900}))
                .with(HeatReading.PART, new HeatReading(12.5, -30.25, 2200))
                .with(Bumpers.PART, new Bumpers(0b100001))
                .with(TruePose.PART, new TruePose(1240, -670, 180));
        assertEquals("""
                robot r1 at step 7, 0.700 s
                  pose       x 1234.5 mm, y -678.3 mm, th 179.5 deg
                  velocity   350.0 mm/s, -12.5 deg/s (left 337.5, right 362.5 mm/s)
                  contact    stalled, 3 collisions, bumper sectors 0,5
                  sonar      5000 742* 650
                  laser      4 readings, nearest 20 mm at reading 2
                  heat       12.50 at -30.3 deg, 2200 mm
                  true pose  x 1240.0 mm, y -670.0 mm, th 180.0 deg
                  messages   0 delivered, 1 errors
                    error: message 3 is addressed to 'nobody'""", RobotUtil.snapshot("r1", s));
    }

    @Test
    void theSnapshotOfAQuietStateSaysWhatIsOff() {
        arrive(new RobotState(1, 100, 0, 0, 0, 0, 0, 0, 0, false, 0));
        String snap = RobotUtil.snapshot(robot);
        assertTrue(snap.contains("  sonar      off\n"), snap);
        assertTrue(snap.contains("  laser      off\n"), snap);
        assertTrue(snap.contains("  heat       off\n"), snap);
        assertTrue(snap.contains("  true pose  not reported\n"), snap);
        assertTrue(snap.contains("bumper sectors none"), snap);
    }

    @Test
    void aRobotThatNeverConnectedShowsStepZero() {
        assertTrue(RobotUtil.snapshot(robot).startsWith("robot r1 at step 0, 0.000 s\n"));
    }
}
