package robosim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import robosim.env.core.RobotSummary;
import robosim.env.net.Departure;
import robosim.env.net.Join;
import robosim.env.net.RunEnding;
import robosim.env.net.RunReport;

/** The Environment's end summary: a line per robot, which says how each robot's part ended. */
class RunReportLinesTest {
    private static RobotSummary at(String name, double x) {
        return new RobotSummary(name, x, 1000, 90, 1234, 1, false, x, 1000, 90, 1, 0, 0, 0);
    }

    /** @return the report of a run of 40 steps (4 s) without timings or a find, every robot of it connected */
    private static RunReport report(String endReason, List<RobotSummary> robots, List<Departure> departures,
                                    List<Join> joins) {
        return new RunReport(40, 4000, endReason, RunEnding.STEP_LIMIT, robots, 0, null, 0, departures, joins, List.of(),
                Map.of(), null);
    }

    @Test
    void eachRobotThatLeftWasDroppedOrWasLostIsMarkedWithTheStepAndTheReason() {
        RunReport report = report("step limit 40 reached",
                List.of(at("r1", 1000), at("r2", 2000), at("r3", 3000), at("r4", 4000)),
                List.of(new Departure("r2", Departure.Kind.LEFT, 2, "the robot's program disconnected"),
                        new Departure("r3", Departure.Kind.LOST, 2, "the connection closed without a bye"),
                        new Departure("r4", Departure.Kind.DROPPED, 2,
                                "it did not send its requests for step 2 within 500 ms")), List.of());
        StringWriter out = new StringWriter();

        EnvCommand.printReport(new PrintWriter(out), report);

        assertEquals(List.of(
                "Run ended after 40 steps (4.0 s simulated): step limit 40 reached",
                "robot r1: pose (1000, 1000, 90.0) travelled 1234 mm, collisions 1, ran to the end",
                "robot r2: pose (2000, 1000, 90.0) travelled 1234 mm, collisions 1, left at step 2: the robot's program"
                        + " disconnected",
                "robot r3: pose (3000, 1000, 90.0) travelled 1234 mm, collisions 1, lost at step 2: the connection closed"
                        + " without a bye",
                "robot r4: pose (4000, 1000, 90.0) travelled 1234 mm, collisions 1, dropped at step 2: it did not send its"
                        + " requests for step 2 within 500 ms"),
                out.toString().lines().toList());
    }

    @Test
    void robotsThatJoinedDuringTheRunAreCountedAndEachSaysHowItLastJoined() {
        RunReport report = report("every robot has disconnected",
                List.of(at("r1", 1000), at("r2", 2000), at("r3", 3000)),
                List.of(new Departure("r2", Departure.Kind.LOST, 5, "the connection closed without a bye"),
                        new Departure("r1", Departure.Kind.LEFT, 40, "done"),
                        new Departure("r2", Departure.Kind.LEFT, 40, "done"),
                        new Departure("r3", Departure.Kind.LEFT, 40, "done")),
                List.of(new Join("r3", Join.Kind.LATE, 3), new Join("r2", Join.Kind.REJOINED, 9)));
        StringWriter out = new StringWriter();

        EnvCommand.printReport(new PrintWriter(out), report);

        assertEquals(List.of(
                "Run ended after 40 steps (4.0 s simulated): every robot has disconnected",
                "Robots joined during the run: 2, went: 4",
                "robot r1: pose (1000, 1000, 90.0) travelled 1234 mm, collisions 1, left at step 40: done",
                "robot r2: pose (2000, 1000, 90.0) travelled 1234 mm, collisions 1, left at step 40: done (rejoined at"
                        + " step 9)",
                "robot r3: pose (3000, 1000, 90.0) travelled 1234 mm, collisions 1, left at step 40: done (joined late at"
                        + " step 3)"),
                out.toString().lines().toList());
    }

    @Test
    void aRobotThatNeverConnectedToTheRunSaysSoRatherThanThatItRanToTheEnd() {
        RunReport report = new RunReport(0, 0, "stopped by control client ctl", RunEnding.STOPPED,
                List.of(at("r1", 1000), at("r2", 2000)), 0, null, 0, List.of(), List.of(), List.of("r2"), Map.of(), null);

        assertEquals("never connected to this run", EnvCommand.howItEnded(report, "r2"));
        assertEquals("ran to the end", EnvCommand.howItEnded(report, "r1"));
    }

    @Test
    void aRobotWhoseAriaClientLeftSaysSoRatherThanThatItRanToTheEnd() {
        RunReport report = report("step limit 40 reached", List.of(at("r1", 1000), at("r2", 2000)),
                List.of(new Departure("r2", Departure.Kind.DROPPED, 7, "it broke a rule")), List.of());
        String left = "its ARIA client left after step 12 (the client sent CLOSE); the robot stood still from then to"
                + " the end";
        StringWriter out = new StringWriter();

        EnvCommand.printReport(new PrintWriter(out), report, robot -> Optional.of(left));

        assertEquals(List.of(
                "Run ended after 40 steps (4.0 s simulated): step limit 40 reached",
                "robot r1: pose (1000, 1000, 90.0) travelled 1234 mm, collisions 1, " + left,
                "robot r2: pose (2000, 1000, 90.0) travelled 1234 mm, collisions 1, dropped at step 7: it broke a rule"),
                out.toString().lines().toList(), "a departure the Environment saw comes first");
    }
}
