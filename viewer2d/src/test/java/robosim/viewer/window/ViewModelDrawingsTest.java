package robosim.viewer.window;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Figure;
import robosim.protocol.Snapshot;
import robosim.viewer.draw.Fixtures;

/** The window's model folds the robots' drawings forward, live and when a replay jumps. */
class ViewModelDrawingsTest {
    private static final Figure CELL = new Figure(Figure.CELLS, "", new double[] {0, 0, 500, 500});
    private static final Snapshot.Drawing MAP = new Snapshot.Drawing("r1", "map", List.of(CELL));

    private static Snapshot step(long step, Snapshot.Drawing... changed) {
        return Fixtures.snapshot(step, Fixtures.robotAtRest()).withDrawings(List.of(changed));
    }

    @Test
    void theSnapshotShownCarriesEveryDrawingSoFar() {
        ViewModel model = new ViewModel();
        model.world(Fixtures.world());
        model.snapshots(List.of(step(1, MAP)));
        model.snapshots(List.of(step(2), step(3)));
        assertEquals(List.of(MAP), model.snapshot().drawings());
    }

    @Test
    void aJumpRebuildsTheDrawingsFromTheHistory() {
        ViewModel model = new ViewModel();
        model.world(Fixtures.world());
        Snapshot.Drawing cleared = new Snapshot.Drawing("r1", "map", List.of());
        model.snapshots(List.of(step(1, MAP), step(2), step(3, cleared)));
        model.jump(List.of(step(1, MAP), step(2)));
        assertEquals(List.of(MAP), model.snapshot().drawings());
        model.jump(List.of(step(1, MAP), step(2), step(3, cleared)));
        assertEquals(List.of(), model.snapshot().drawings());
    }

    @Test
    void aNewWorldForgetsThem() {
        ViewModel model = new ViewModel();
        model.world(Fixtures.world());
        model.snapshots(List.of(step(1, MAP)));
        model.world(Fixtures.world());
        model.snapshots(List.of(step(2)));
        assertEquals(List.of(), model.snapshot().drawings());
    }
}
