package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * ArActionKeydrive.cpp's keys: it takes UP, DOWN, LEFT, RIGHT and SPACE of the program's key handler
 * when added to a robot and when activated, and gives them up when deactivated.
 */
@Timeout(10)
class ArActionKeydriveKeysTest {
    static final String UP = "\u001b[A";
    static final String DOWN = "\u001b[B";
    static final String RIGHT = "\u001b[C";
    static final String LEFT = "\u001b[D";

    static ArKeyHandler keys(String text) {
        ArKeyHandler h = new ArKeyHandler(true, false,
                new ByteArrayInputStream(text.getBytes(StandardCharsets.ISO_8859_1)), true);
        Aria.setKeyHandler(h);
        return h;
    }

    @AfterEach
    void noKeyHandler() {
        Aria.setKeyHandler(null);
    }

    @Test
    void addedToARobotItDrivesFromTheKeyHandlersArrows() {
        ArKeyHandler h = keys(UP + UP + UP + DOWN + LEFT);
        ActionFixture f = new ActionFixture();
        ArActionKeydrive drive = f.attach(new ArActionKeydrive());
        f.at(0, 0, 0, 0);
        h.checkKeys();
        ArActionDesired d = ActionFixture.fire(drive);
        assertEquals(50, d.getVel());
        assertEquals(8, d.getDeltaHeading());
    }

    @Test
    void spaceFromTheKeyHandlerStops() {
        ArKeyHandler h = keys(" ");
        ActionFixture f = new ActionFixture();
        ArActionKeydrive drive = f.attach(new ArActionKeydrive());
        f.at(0, 0, 0, 0);
        drive.up();
        drive.up();
        assertEquals(50, ActionFixture.fire(drive).getVel());
        drive.right();
        h.checkKeys();
        ArActionDesired d = ActionFixture.fire(drive);
        assertEquals(0, d.getVel());
        assertEquals(0, d.getDeltaHeading());
    }

    @Test
    void asInARIAPressesBeforeSpaceInTheSameCycleStillCount() {
        ArKeyHandler h = keys(UP + UP + " ");
        ActionFixture f = new ActionFixture();
        ArActionKeydrive drive = f.attach(new ArActionKeydrive());
        f.at(0, 0, 0, 0);
        h.checkKeys();
        assertEquals(50, ActionFixture.fire(drive).getVel(), "space zeroes the speed, not the presses not yet applied");
    }

    @Test
    void deactivatedItGivesUpItsKeysAndActivatedTakesThemAgain() {
        ArKeyHandler h = keys("");
        ActionFixture f = new ActionFixture();
        ArActionKeydrive drive = f.attach(new ArActionKeydrive());
        assertFalse(h.addKeyHandler(ArKeyHandler.UP, () -> { }), "the keydrive holds UP");
        drive.deactivate();
        Runnable other = () -> { };
        assertTrue(h.addKeyHandler(ArKeyHandler.UP, other), "UP is free once it is deactivated");
        h.remKeyHandler(other);
        drive.activate();
        assertFalse(h.addKeyHandler(ArKeyHandler.SPACE, () -> { }), "activated, it holds its keys again");
    }

    @Test
    void withoutAKeyHandlerItIsDrivenByItsMethods() {
        Aria.setKeyHandler(null);
        ActionFixture f = new ActionFixture();
        ArActionKeydrive drive = f.attach(new ArActionKeydrive());
        f.at(0, 0, 0, 0);
        drive.up();
        assertEquals(25, ActionFixture.fire(drive).getVel());
    }
}
