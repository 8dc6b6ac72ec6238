package robosim.viewer.window;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Snapshot;
import robosim.viewer.draw.Fixtures;

/** The window's log shows a robot's request to end the run as one line, and not its metrics. */
class ViewModelRunEventsTest {
    @Test
    void theEndRequestIsALineAndTheMetricsAreNot() {
        ViewModel model = new ViewModel();
        model.world(Fixtures.world());

        model.snapshots(List.of(Fixtures.snapshot(811, Fixtures.robotAtRest())
                        .withRunEvents(List.of(new Snapshot.Metric("r1", "cells", 40)), null),
                Fixtures.snapshot(812, Fixtures.robotAtRest()).withRunEvents(List.of(
                        new Snapshot.Metric("r1", "cells", 41)), new Snapshot.EndRequest("r1", 812, "gold found"))));

        assertEquals(List.of("step 812: robot r1 ended the run: gold found"), model.messages());
    }

    @Test
    void aReplayThatJumpsPastTheEndRequestShowsIt() {
        ViewModel model = new ViewModel();
        model.world(Fixtures.world());
        Snapshot ended = Fixtures.snapshot(2, Fixtures.robotAtRest())
                .withRunEvents(List.of(), new Snapshot.EndRequest("r1", 2, "done exploring"));

        model.jump(List.of(Fixtures.snapshot(1, Fixtures.robotAtRest()), ended));

        assertEquals(List.of("step 2: robot r1 ended the run: done exploring"), model.messages());
    }
}
