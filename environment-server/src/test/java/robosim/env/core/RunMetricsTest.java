package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;
import robosim.protocol.Snapshot;

/**
 * The metrics robots report and their requests to end the run, as the core keeps them: the last value
 * of each name, at most 64 names a robot, the first end request of the run.
 */
class RunMetricsTest {
    private static Simulation threeRobots() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(), Worlds.robot("a", 2000, 5000, 0),
                Worlds.robot("b", 5000, 5000, 0), Worlds.robot("c", 8000, 5000, 0)));
        sim.setConnected("a", true);
        sim.setConnected("b", true);
        sim.setConnected("c", true);
        return sim;
    }

    private static Command.ReportMetric metric(String name, double value) {
        return new Command.ReportMetric(name, value);
    }

    @Test
    void theLastValueOfEachNameIsKeptInTheOrderTheNamesWereFirstReported() {
        Simulation sim = threeRobots();
        sim.step(Map.of("b", List.of(metric("cells", 1), metric("frontier", 9))));
        sim.step(Map.of("b", List.of(metric("turns", 2), metric("cells", 5), metric("cells", 6))));

        Map<String, Double> b = new LinkedHashMap<>();
        b.put("cells", 6.0);
        b.put("frontier", 9.0);
        b.put("turns", 2.0);
        assertEquals(List.of("cells", "frontier", "turns"), List.copyOf(sim.metrics().get("b").keySet()));
        assertEquals(b, sim.metrics().get("b"));
    }

    @Test
    void everyRobotIsInTheMetricsInTheWorldsOrderThoseWithoutReportsEmpty() {
        Simulation sim = threeRobots();
        sim.step(Map.of("c", List.of(metric("x", 1)), "a", List.of(metric("y", 2))));

        assertEquals(List.of("a", "b", "c"), List.copyOf(sim.metrics().keySet()));
        assertEquals(Map.of(), sim.metrics().get("b"));
        assertThrows(UnsupportedOperationException.class, () -> sim.metrics().get("a").put("z", 3.0));
    }

    @Test
    void theSnapshotCarriesTheStepsReportsOnlyInThatStep() {
        Simulation sim = threeRobots();
        sim.step(Map.of("a", List.of(metric("cells", 1), metric("turns", 4), metric("cells", 2)),
                "b", List.of(metric("cells", 7))));

        assertEquals(List.of(new Snapshot.Metric("a", "cells", 2), new Snapshot.Metric("a", "turns", 4),
                new Snapshot.Metric("b", "cells", 7)), sim.snapshot().metrics());
        sim.step(Map.of());
        assertEquals(List.of(), sim.snapshot().metrics());
        assertEquals(2.0, sim.metrics().get("a").get("cells"), "still kept for the report");
    }

    @Test
    void aSixtyFifthNameIsRefusedWithAnErrorTheRobotReadsNextAndNotKept() {
        Simulation sim = threeRobots();
        List<Command> sixtyFour = new ArrayList<>();
        for (int i = 1; i <= 64; i++) {
            sixtyFour.add(metric("m" + i, i));
        }
        sim.step(Map.of("a", sixtyFour));
        assertEquals(List.of(), sim.state("a").errors());

        sim.step(Map.of("a", List.of(metric("m65", 65), metric("m1", -1))));

        assertEquals(List.of("step 2: robot a has reported 64 metrics, the most a robot may report; metric m65 was"
                + " not kept"), sim.state("a").errors());
        assertEquals(64, sim.metrics().get("a").size());
        assertNull(sim.metrics().get("a").get("m65"));
        assertEquals(-1.0, sim.metrics().get("a").get("m1"), "a name it has goes on changing");
        assertEquals(List.of(new Snapshot.Metric("a", "m1", -1)), sim.snapshot().metrics());
        sim.step(Map.of("b", List.of(metric("m65", 65))));
        assertEquals(65.0, sim.metrics().get("b").get("m65"), "the cap is each robot's own");
    }

    @Test
    void theFirstEndRequestOfTheRunIsKeptTheRobotsInTheWorldsOrder() {
        Simulation sim = threeRobots();
        sim.step(Map.of());
        assertNull(sim.endRequest());

        sim.step(Map.of("c", List.of(new Command.EndRun("found it too")), "b",
                List.of(new Command.Say("done"), new Command.EndRun("gold found"), new Command.EndRun("again"))));
        sim.step(Map.of("a", List.of(new Command.EndRun("late"))));

        assertEquals(new Snapshot.EndRequest("b", 2, "gold found"), sim.endRequest());
    }

    @Test
    void theEndRequestIsInTheSnapshotOfItsStepOnly() {
        Simulation sim = threeRobots();
        sim.step(Map.of("a", List.of(new Command.EndRun("done exploring"))));
        assertEquals(new Snapshot.EndRequest("a", 1, "done exploring"), sim.snapshot().endRequest());

        sim.step(Map.of());

        assertNull(sim.snapshot().endRequest());
    }
}
