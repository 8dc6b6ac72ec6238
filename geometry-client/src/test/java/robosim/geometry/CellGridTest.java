package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.locationtech.jts.geom.Envelope;

/** The grid finds every item whose envelope meets a query's, once each, in id order. */
class CellGridTest {
    private static Envelope randomBox(Random rnd, double span, double maxSide) {
        double x = rnd.nextDouble() * span - span * 0.1;
        double y = rnd.nextDouble() * span - span * 0.1;
        return new Envelope(x, x + rnd.nextDouble() * maxSide, y, y + rnd.nextDouble() * maxSide);
    }

    /** What a scan of all bodies keeps: those whose envelope intersects, in id order. */
    private static int[] scan(List<Envelope> bodies, Envelope q) {
        return java.util.stream.IntStream.range(0, bodies.size()).filter(i -> bodies.get(i).intersects(q)).toArray();
    }

    private static int[] kept(int[] found, List<Envelope> bodies, Envelope q) {
        return Arrays.stream(found).filter(i -> bodies.get(i).intersects(q)).toArray();
    }

    @ParameterizedTest(name = "cells of {0} mm")
    @ValueSource(doubles = {37, 250, 2000, 1e9})
    void queriesFindWhatAScanFindsWhileBodiesMove(double cell) {
        Random rnd = new Random(11);
        double span = 20000;
        // the grid covers only part of where bodies go: outside it they fall into the border cells
        CellGrid grid = new CellGrid(new Envelope(0, span * 0.8, 0, span * 0.8), cell);
        List<Envelope> bodies = new ArrayList<>();
        for (int i = 0; i < 300; i++) {
            // some bodies are big, spanning many cells
            Envelope e = randomBox(rnd, span, i % 10 == 0 ? 4000 : 600);
            bodies.add(e);
            grid.add(i, e);
        }
        for (int round = 0; round < 12; round++) {
            for (int k = 0; k < 200; k++) {
                Envelope q = randomBox(rnd, span, k % 5 == 0 ? 6000 : 1200);
                int[] found = grid.query(q);
                for (int i = 1; i < found.length; i++) {
                    assertTrue(found[i - 1] < found[i], "ascending, each once: " + Arrays.toString(found));
                }
                assertArrayEquals(scan(bodies, q), kept(found, bodies, q), "round " + round + ", query " + q);
            }
            for (int i = 0; i < bodies.size(); i++) {
                if (rnd.nextInt(3) == 0) {
                    Envelope e = bodies.get(i);
                    // small steps cross cell borders now and then; some jumps go far
                    double dx = rnd.nextInt(20) == 0 ? rnd.nextGaussian() * 8000 : rnd.nextGaussian() * 150;
                    double dy = rnd.nextInt(20) == 0 ? rnd.nextGaussian() * 8000 : rnd.nextGaussian() * 150;
                    Envelope moved = new Envelope(e.getMinX() + dx, e.getMaxX() + dx, e.getMinY() + dy, e.getMaxY() + dy);
                    bodies.set(i, moved);
                    grid.move(i, moved);
                }
            }
        }
    }

    @Test
    void aQueryTouchingABodyOnlyAtItsEdgeFindsIt() {
        CellGrid grid = new CellGrid(new Envelope(0, 10000, 0, 10000), 1000);
        Envelope body = new Envelope(1000, 2000, 1000, 2000);
        grid.add(0, body);
        // closed envelopes: touching counts as meeting, as JTS's Envelope.intersects has it
        assertArrayEquals(new int[] {0}, grid.query(new Envelope(2000, 3000, 500, 2000)));
        assertArrayEquals(new int[] {0}, grid.query(new Envelope(0, 1000, 0, 1000)));
        assertArrayEquals(new int[0], grid.query(new Envelope(5000, 6000, 5000, 6000)));
        assertArrayEquals(new int[0], grid.query(new Envelope()));
    }

    @Test
    void aHugeExtentGetsLargerCells() {
        CellGrid grid = new CellGrid(new Envelope(0, 1e9, 0, 1e9), 100);
        assertTrue(grid.cellSize() >= 1e9 / Math.sqrt(CellGrid.MAX_CELLS), "cell " + grid.cellSize());
        grid.add(0, new Envelope(5, 6, 5, 6));
        assertArrayEquals(new int[] {0}, grid.query(new Envelope(0, 10, 0, 10)));
    }

    @Test
    void idsComeInOrder() {
        CellGrid grid = new CellGrid(new Envelope(0, 100, 0, 100), 10);
        grid.add(0, new Envelope(1, 2, 1, 2));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> grid.add(5, new Envelope(1, 2, 1, 2)));
        assertEquals("5 was supplied for id: the next item's id is 1", e.getMessage());
    }
}
