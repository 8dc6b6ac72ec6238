package robosim.panel.model;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import robosim.protocol.RunStatus;

class RobotRowsTest {
    private static final RunStatus.RobotStatus R1 = new RunStatus.RobotStatus("r1", "p3dx",
            "program at 127.0.0.1:40312", true, 1500.4, -250.6, 89.6, 300, -15.25, false, 2, 5, 3, 42);
    private static final RunStatus.RobotStatus R2 = new RunStatus.RobotStatus("r2", "p3at", "", false, 0, 0, 0, 0, 0,
            true, 0, 0, 0, 0);

    @Test
    void aRowShowsEveryColumnAsAUserReadsIt() {
        RunStatus s = new RunStatus(1, "demo", 42, 4200, false, 0, List.of(R1));

        assertEquals(List.of(List.of("r1", "p3dx", "program at 127.0.0.1:40312", "1500, -251, 90", "300, -15.3",
                "no", "2", "5", "3", "42", "connected")), RobotRows.of(s));
    }

    @Test
    void aRobotWithoutProgramBeforeTheFirstStepIsNotConnectedAndDrivenByNothing() {
        List<String> row = RobotRows.of(new RunStatus(1, "demo", 0, 0, true, 0, List.of(R2))).get(0);

        assertEquals(List.of("-", "stalled", "not connected yet"), List.of(row.get(2), row.get(5),
                row.get(RobotRows.CONNECTION)));
    }

    @Test
    void aRobotOfAnOpenWorldThatNeverConnectedIsNotConnectedYetAfterSteps() {
        assertEquals("not connected yet", RobotRows.of(new RunStatus(1, "open", 7, 700, false, 0, List.of(R2))).get(0)
                .get(RobotRows.CONNECTION));
    }

    @Test
    void aRobotThatAnsweredStepsOrWasSeenConnectedAndIsNoLongerHasGone() {
        RunStatus.RobotStatus answered = new RunStatus.RobotStatus("r2", "p3at", "", false, 0, 0, 0, 0, 0, false, 0, 0,
                0, 5);
        assertEquals("gone", RobotRows.of(new RunStatus(1, "demo", 7, 700, false, 0, List.of(answered))).get(0)
                .get(RobotRows.CONNECTION));
        assertEquals("gone", RobotRows.of(new RunStatus(1, "demo", 7, 700, false, 0, List.of(R2)), Set.of("r2")).get(0)
                .get(RobotRows.CONNECTION));
    }

    @Test
    void theRobotsSeenConnectedAreForgottenWhenTheRunStartsAgain() {
        SeenRobots seen = new SeenRobots();
        RunStatus.RobotStatus r2Connected = new RunStatus.RobotStatus("r2", "p3at", "program at 127.0.0.1:1", true, 0,
                0, 0, 0, 0, false, 0, 0, 0, 0);
        seen.update(new RunStatus(1, "demo", 3, 300, false, 0, List.of(r2Connected)));

        assertEquals(Set.of("r2"), seen.update(new RunStatus(2, "demo", 9, 900, false, 0, List.of(R2))));
        assertEquals(Set.of(), seen.update(new RunStatus(3, "demo", 0, 0, false, 0, List.of(R2))), "restarted");
        seen.update(new RunStatus(4, "demo", 2, 200, false, 0, List.of(r2Connected)));
        assertEquals(Set.of(), seen.update(new RunStatus(5, "other", 2, 200, false, 0, List.of(R2))), "another world");
    }

    @Test
    void aConnectedRobotThatDidNotAnswerTheLastStepIsBehind() {
        assertEquals("connected, behind", RobotRows.of(new RunStatus(1, "demo", 43, 4300, false, 0, List.of(R1)))
                .get(0).get(RobotRows.CONNECTION));
    }

    @Test
    void theRunLineSaysWorldStepPausedPaceAndRobotsConnected() {
        RunStatus s = new RunStatus(1, "demo", 42, 4200, true, 1, List.of(R1, R2));

        assertEquals("world demo - step 42 (4.2 s) - paused - pace real time - 1 of 2 robots connected",
                RobotRows.runLine(s));
    }
}
