package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;
import robosim.protocol.Figure;
import robosim.protocol.FrameReader;
import robosim.protocol.MessageCodec;
import robosim.protocol.Snapshot;

/** The robots' drawings: kept per robot and layer, and in a snapshot only in the step they changed. */
class DrawingsTest {
    private static final Figure CELL = new Figure(Figure.CELLS, "", new double[] {0, 0, 500, 500});

    private static Simulation twoRobots() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(), Worlds.robot("a", 2000, 5000, 0),
                Worlds.robot("b", 8000, 5000, 0)));
        sim.setConnected("a", true);
        sim.setConnected("b", true);
        return sim;
    }

    private static Command.Draw draw(String layer, Figure... figures) {
        return new Command.Draw(layer, List.of(figures));
    }

    @Test
    void aDrawingIsInTheSnapshotOfTheStepItWasSentOnly() {
        Simulation sim = twoRobots();
        sim.step(Map.of("a", List.of(draw("map", CELL))));
        assertEquals(List.of(new Snapshot.Drawing("a", "map", List.of(CELL))), sim.snapshot().drawings());
        sim.step(Map.of());
        assertEquals(List.of(), sim.snapshot().drawings());
        assertEquals(List.of(new Snapshot.Drawing("a", "map", List.of(CELL))), sim.drawings(), "it is still drawn");
    }

    @Test
    void anEmptyListClearsTheLayer() {
        Simulation sim = twoRobots();
        sim.step(Map.of("a", List.of(draw("map", CELL), draw("frontier", CELL))));
        sim.step(Map.of("a", List.of(draw("map"))));
        assertEquals(List.of(new Snapshot.Drawing("a", "map", List.of())), sim.snapshot().drawings());
        assertEquals(List.of(new Snapshot.Drawing("a", "frontier", List.of(CELL))), sim.drawings());
    }

    @Test
    void aLayerDrawnTwiceInAStepIsSentAsItWasLastDrawn() {
        Simulation sim = twoRobots();
        Figure dot = new Figure(Figure.DOTS, "red", new double[] {1, 2});
        sim.step(Map.of("a", List.of(draw("map", CELL), draw("map", dot))));
        assertEquals(List.of(new Snapshot.Drawing("a", "map", List.of(dot))), sim.snapshot().drawings());
    }

    @Test
    void aRobotThatLeavesLosesItsDrawingsInTheNextSnapshot() {
        Simulation sim = twoRobots();
        sim.step(Map.of("a", List.of(draw("map", CELL)), "b", List.of(draw("map", CELL))));
        sim.setConnected("a", false);
        sim.step(Map.of());
        assertEquals(List.of(new Snapshot.Drawing("a", "map", List.of())), sim.snapshot().drawings());
        assertEquals(List.of(new Snapshot.Drawing("b", "map", List.of(CELL))), sim.drawings());
    }

    @Test
    void aLayerThatWouldBringAllTheDrawingsPastTheirCapIsRefused() {
        Simulation sim = twoRobots();
        Figure full = new Figure(Figure.DOTS, "", new double[Figure.MAX_NUMBERS]);
        List<Command> a = new ArrayList<>();
        List<Command> b = new ArrayList<>();
        for (int i = 1; i <= 5; i++) {
            a.add(draw("a" + i, full));
            b.add(draw("b" + i, full));
        }
        sim.step(Map.of("a", a, "b", b));
        assertEquals(10, sim.drawings().size(), "200000 numbers in all");
        int bytes = new MessageCodec().encode(sim.snapshot().withDrawings(sim.drawings())).length;
        assertTrue(bytes < FrameReader.DEFAULT_MAX_FRAME, "all of them fit a viewer's frame: " + bytes + " bytes");
        sim.step(Map.of("a", List.of(draw("a1", full), draw("more", CELL))));
        List<String> errors = sim.state("a").errors();
        assertEquals(List.of("step 2: robot a's layer more of 4 numbers would bring the robots' drawings to 200004"
                + " numbers, more than the 200000 they may hold together; it was not drawn"), errors);
        sim.setConnected("b", false);
        sim.step(Map.of("a", List.of(draw("more", CELL))));
        assertTrue(sim.state("a").errors().isEmpty(), "a robot that left made room");
    }

    @Test
    void aNinthLayerIsRefusedAndTheRobotGoesOn() {
        Simulation sim = twoRobots();
        List<Command> nine = new ArrayList<>();
        for (int i = 1; i <= 9; i++) {
            nine.add(draw("layer" + i, CELL));
        }
        nine.add(new Command.Say("still here"));
        sim.step(Map.of("a", nine));
        assertEquals(8, sim.drawings().size());
        List<String> errors = sim.state("a").errors();
        assertEquals(1, errors.size(), errors.toString());
        assertTrue(errors.get(0).startsWith("step 1: robot a has 8 drawing layers"), errors.get(0));
        assertTrue(errors.get(0).contains("layer layer9 was not drawn"), errors.get(0));
        assertEquals("still here", sim.snapshot().said().get(0).text());
        sim.step(Map.of("a", List.of(draw("layer1"), draw("layer9", CELL))));
        assertEquals(8, sim.drawings().size(), "a cleared layer makes room");
        assertTrue(sim.state("a").errors().isEmpty());
    }
}
