package robosim.panel.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;
import robosim.protocol.CommsUpdate;

class CommsChangeTest {
    @Test
    void emptyFieldsKeepTheirSettings() {
        assertEquals(new CommsUpdate(null, false, 2, null, null), CommsChange.parse("", "no", "2", " ", ""));
    }

    @Test
    void everyFieldGivenIsSent() {
        assertEquals(new CommsUpdate(5000.0, true, 1, 0.25, 512), CommsChange.parse("5000", "yes", "1", "0.25", "512"));
    }

    @Test
    void aLossAboveOneIsRefusedWithTheRule() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> CommsChange.parse("", "", "", "1.5", ""));

        assertEquals("Loss: a number from 0 to 1, got '1.5'", e.getMessage());
    }

    @Test
    void aFractionalLatencyIsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> CommsChange.parse("", "", "1.5", "", ""));

        assertEquals("Latency: a whole number, got '1.5'", e.getMessage());
    }

    @Test
    void nothingToChangeIsSaid() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> CommsChange.parse("", "", "", "", ""));

        assertEquals("Comms: give at least one setting to change", e.getMessage());
    }

    @Test
    void theSettingsInForceAreDescribedInOneLine() {
        assertEquals("range 5000 mm, walls block true, latency 1, loss 0.250, max 512 bytes",
                CommsChange.describe(new CommsUpdate(5000.0, true, 1, 0.25, 512)));
    }
}
