package robosim.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

class DriveFieldsTest {
    @Test
    void aDistanceIsReadInMillimetres() {
        assertEquals(1500.5, DriveFields.distance("1500.5"));
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "abc", "NaN", "Infinity", "1e3", "0x10", "5 m"})
    void aDistanceThatIsNoPlainNumberIsRefused(String text) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> DriveFields.distance(text));
        assertEquals("'" + text.trim() + "' was supplied for move distance: it is a distance in mm, e.g. 500, or -250"
                + " to back up", e.getMessage());
    }

    @Test
    void aDistanceOfZeroOrPastTheLimitIsRefused() {
        assertEquals("'0' was supplied for move distance: it is from -100000 to 100000 mm, and not 0",
                assertThrows(IllegalArgumentException.class, () -> DriveFields.distance("0")).getMessage());
        assertThrows(IllegalArgumentException.class, () -> DriveFields.distance("100001"));
    }

    @Test
    void aHeadingOutsideMinus180To180IsRefused() {
        assertEquals(180.0, DriveFields.heading("180"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> DriveFields.heading("270"));
        assertEquals("'270' was supplied for heading: a heading is -180 to 180 degrees, counter-clockwise from the x axis",
                e.getMessage());
    }
}
