package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.ValueSource;
import robosim.protocol.MessageCodec.Format;

/** A robot's drawings: the command, the figures' rules, and the snapshots that carry them. */
class DrawingMessagesTest {
    private static final Figure CELL = new Figure(Figure.CELLS, "", new double[] {0, 0, 500, 500});

    private static Message roundTrip(Format format, Message message) throws FrameException {
        MessageCodec codec = new MessageCodec(format);
        return codec.decode(codec.encode(message));
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void aDrawCommandRoundTrips(Format format) throws FrameException {
        Command.Draw draw = new Command.Draw("frontier", List.of(CELL,
                new Figure(Figure.LINE, "red", new double[] {0, 0, 1000, 250.5}),
                new Figure(Figure.POLYGON, "#00FF7f", new double[] {0, 0, 10, 0, 10, 10}),
                new Figure(Figure.DOTS, null, new double[] {-3.5, 4})));
        RobotRequests decoded = (RobotRequests) roundTrip(format, new RobotRequests(7, List.of(draw)));
        assertEquals(List.of(draw), decoded.commands());
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void aSnapshotCarriesTheDrawingsThatChanged(Format format) throws FrameException {
        Snapshot s = new Snapshot(4, 400, List.of()).withDrawings(List.of(
                new Snapshot.Drawing("r1", "map", List.of(CELL)), new Snapshot.Drawing("r2", "map", List.of())));
        assertEquals(s.drawings(), ((Snapshot) roundTrip(format, s)).drawings());
    }

    @Test
    void aSnapshotWithoutDrawingsLeavesThemOffTheWire() {
        String json = new String(new MessageCodec(Format.JSON).encode(new Snapshot(4, 400, List.of())),
                StandardCharsets.UTF_8);
        assertFalse(json.contains("drawings"), json);
    }

    @Test
    void recordingsFromBeforeDrawingsReadAsNone() throws FrameException {
        Snapshot s = (Snapshot) new MessageCodec(Format.JSON).decode(
                "{\"type\":\"frame\",\"step\":1,\"timeMs\":100,\"robots\":[]}".getBytes(StandardCharsets.UTF_8));
        assertEquals(List.of(), s.drawings());
    }

    @Test
    void aColourIsKeptAsHexAndNoneAsEmpty() {
        assertEquals("#ff0000", new Figure(Figure.DOTS, "Red", new double[] {1, 2}).color());
        assertEquals("", new Figure(Figure.DOTS, null, new double[] {1, 2}).color());
    }

    @Test
    void aFigureKeepsItsOwnCopyOfTheNumbers() {
        double[] xy = {0, 0, 1, 1};
        Figure f = new Figure(Figure.CELLS, "", xy);
        xy[0] = 99;
        f.xy()[1] = 99;
        assertEquals(0, f.at(0));
        assertEquals(0, f.at(1));
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "has space", "a/b", "x123456789012345678901234567890123"})
    void aBadLayerIsRefused(String layer) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Command.Draw(layer, List.of()));
        assertEquals("'" + layer + "' was supplied for a drawing's layer: 1 to 32 letters, digits, '.', '_' or '-'",
                e.getMessage());
    }

    @Test
    void aNaNCoordinateIsRefusedNamingIt() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Figure(Figure.LINE, "", new double[] {0, 0, Double.NaN, 1}));
        assertEquals("NaN was supplied for xy[2] of a line figure: it must be a finite number", e.getMessage());
    }

    @Test
    void aWrongNumberOfCoordinatesForTheKindIsRefused() {
        IllegalArgumentException cells = assertThrows(IllegalArgumentException.class,
                () -> new Figure(Figure.CELLS, "", new double[] {0, 0, 1, 1, 2, 2}));
        assertEquals("6 numbers were supplied for a cells figure: 4 (x0, y0, x1, y1) per cell, at least 4",
                cells.getMessage());
        IllegalArgumentException polygon = assertThrows(IllegalArgumentException.class,
                () -> new Figure(Figure.POLYGON, "", new double[] {0, 0, 1, 1}));
        assertEquals("4 numbers were supplied for a polygon figure: 2 (x, y) per point, at least 6",
                polygon.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new Figure(Figure.DOTS, "", new double[] {1}));
        assertThrows(IllegalArgumentException.class, () -> new Figure(Figure.LINE, "", new double[] {1, 2}));
    }

    @Test
    void anUnknownKindOrColourIsRefused() {
        IllegalArgumentException kind = assertThrows(IllegalArgumentException.class,
                () -> new Figure("circle", "", new double[] {1, 2}));
        assertEquals("'circle' was supplied for a figure's kind: it is one of cells, line, polygon or dots",
                kind.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new Figure(Figure.DOTS, "mauve", new double[] {1, 2}));
    }

    @Test
    void tooManyNumbersInADrawingAreRefused() {
        Figure half = new Figure(Figure.DOTS, "", new double[10_002]);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Command.Draw("map", List.of(half, half)));
        assertEquals("20004 numbers were supplied for layer map: at most 20000 in all its figures", e.getMessage());
        IllegalArgumentException one = assertThrows(IllegalArgumentException.class,
                () -> new Figure(Figure.DOTS, "", new double[20_002]));
        assertEquals("20002 numbers were supplied for a dots figure: at most 20000", one.getMessage());
    }

    @Test
    void tooManyFiguresAreRefused() {
        List<Figure> figures = new ArrayList<>(Collections.nCopies(257, CELL));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Command.Draw("map", figures));
        assertEquals("257 figures were supplied for layer map: at most 256", e.getMessage());
    }

    @Test
    void aBadFigureOnTheWireIsRefusedAsAFrameError() {
        byte[] payload = ("{\"type\":\"robotRequests\",\"step\":5,\"commands\":[{\"cmd\":\"draw\",\"layer\":\"map\","
                + "\"figures\":[{\"kind\":\"cells\",\"color\":\"\",\"xy\":[0,0,1]}]}]}").getBytes(StandardCharsets.UTF_8);
        FrameException e = assertThrows(FrameException.class, () -> new MessageCodec(Format.JSON).decode(payload));
        assertTrue(e.getMessage().contains("3 numbers were supplied for a cells figure"), e.getMessage());
    }
}
