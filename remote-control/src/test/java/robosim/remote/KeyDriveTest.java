package robosim.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class KeyDriveTest {
    @Test
    void upHeldDrivesForwardAtTheTranslationalSpeed() {
        KeyDrive keys = new KeyDrive();
        assertTrue(keys.press(KeyDrive.Key.FORWARD, 0));
        assertEquals(new KeyDrive.Drive(300, 0), keys.drive(300, 30));
    }

    @Test
    void upAndLeftHeldDriveAnArc() {
        KeyDrive keys = new KeyDrive();
        keys.press(KeyDrive.Key.FORWARD, 0);
        keys.press(KeyDrive.Key.LEFT, 10);
        assertEquals(new KeyDrive.Drive(300, 30), keys.drive(300, 30));
    }

    @Test
    void downAndRightHeldBackUpTurningClockwise() {
        KeyDrive keys = new KeyDrive();
        keys.press(KeyDrive.Key.BACK, 0);
        keys.press(KeyDrive.Key.RIGHT, 0);
        assertEquals(new KeyDrive.Drive(-200, -20), keys.drive(200, 20));
    }

    @Test
    void oppositeKeysCancel() {
        KeyDrive keys = new KeyDrive();
        keys.press(KeyDrive.Key.FORWARD, 0);
        keys.press(KeyDrive.Key.BACK, 0);
        assertTrue(keys.drive(300, 30).isStop());
    }

    @Test
    void aReleaseCountsOnlyAfterTheGraceTime() {
        KeyDrive keys = new KeyDrive();
        keys.press(KeyDrive.Key.FORWARD, 1000);
        keys.release(KeyDrive.Key.FORWARD, 2000);
        assertFalse(keys.due(2000 + KeyDrive.RELEASE_GRACE_MS - 1), "still within the grace time");
        assertEquals(new KeyDrive.Drive(300, 0), keys.drive(300, 30));
        assertTrue(keys.due(2000 + KeyDrive.RELEASE_GRACE_MS));
        assertTrue(keys.drive(300, 30).isStop());
    }

    @Test
    void autoRepeatsReleaseAndPressPairsKeepTheRobotDriving() {
        KeyDrive keys = new KeyDrive();
        keys.press(KeyDrive.Key.FORWARD, 0);
        for (long t = 30; t < 600; t += 30) {
            keys.release(KeyDrive.Key.FORWARD, t);
            assertFalse(keys.press(KeyDrive.Key.FORWARD, t + 1), "a repeat is no change");
            assertFalse(keys.due(t + 20));
        }
        assertEquals(new KeyDrive.Drive(300, 0), keys.drive(300, 30));
    }

    @Test
    void clearLetsGoOfEverything() {
        KeyDrive keys = new KeyDrive();
        keys.press(KeyDrive.Key.LEFT, 0);
        keys.release(KeyDrive.Key.LEFT, 5);
        keys.clear();
        assertFalse(keys.anyHeld());
        assertFalse(keys.releasePending());
    }
}
