package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;

/** ArActionKeydrive.cpp's rules: key presses step the speed and the turn, within the limits. */
class ArActionKeydriveTest {
    private final ActionFixture f = new ActionFixture();
    private final ArActionKeydrive keys = f.attach(new ArActionKeydrive());

    @Test
    void eachUpPressAddsTheVelocityIncrementAndTheSpeedStays() {
        f.at(0, 0, 0, 0);
        keys.up();
        keys.up();
        keys.up();
        assertEquals(75, ActionFixture.fire(keys).getVel());
        assertEquals(75, ActionFixture.fire(keys).getVel());
        keys.down();
        assertEquals(50, ActionFixture.fire(keys).getVel());
    }

    @Test
    void theSpeedStopsAtTheMaximumEitherWay() {
        f.at(0, 0, 0, 0);
        for (int i = 0; i < 20; i++) {
            keys.down();
        }
        assertEquals(-400, ActionFixture.fire(keys).getVel());
    }

    @Test
    void leftPressesTurnOnceUpToTheMaximumTurnAmount() {
        f.at(0, 0, 0, 0);
        for (int i = 0; i < 4; i++) {
            keys.left();
        }
        assertEquals(24, ActionFixture.fire(keys).getDeltaHeading());
        assertEquals(0, ActionFixture.fire(keys).getDeltaHeading());
        keys.right();
        assertEquals(-8, ActionFixture.fire(keys).getDeltaHeading());
    }

    @Test
    void spaceStops() {
        f.at(0, 0, 0, 0);
        keys.up();
        keys.left();
        ActionFixture.fire(keys);
        keys.left();
        keys.space();
        ArActionDesired d = ActionFixture.fire(keys);
        assertEquals(0, d.getVel());
        assertEquals(0, d.getDeltaHeading());
    }

    @Test
    void theSpeedIsHeldWithinAHigherPrioritysMaximum() {
        f.at(0, 0, 0, 0);
        for (int i = 0; i < 8; i++) {
            keys.up();
        }
        ActionFixture.fire(keys);
        ArActionDesired limited = new ArActionDesired();
        limited.setMaxVel(120);
        assertEquals(120, keys.fire(limited).getVel());
    }

    @Test
    void afterAHigherPriorityTookTheVelocityItStartsFromTheRobotsOwn() {
        f.at(0, 0, 0, 0);
        for (int i = 0; i < 8; i++) {
            keys.up();
        }
        ActionFixture.fire(keys);
        ArActionDesired taken = new ArActionDesired();
        taken.setVel(0);
        f.at(0, 0, 0, 90);
        assertEquals(90, keys.fire(taken).getVel());
    }

    @Test
    void onARobotThePressesBecomeVelocityAndHeadingCommands() {
        List<Command> sent = new ArrayList<>();
        ArRobot robot = new ArRobot("r", "127.0.0.1", 5000, Cycles.p3dx()) {
            @Override
            protected void request(Command command) {
                sent.add(command);
            }
        };
        ArActionKeydrive drive = new ArActionKeydrive();
        robot.addAction(drive, 50);
        drive.up();
        drive.up();
        drive.left();
        Cycles.cycle(robot, 100, 0, 0, 0);
        assertTrue(sent.contains(new Command.SetVel(50)), sent.toString());
        assertTrue(sent.contains(new Command.SetHeading(8)), sent.toString());
    }
}
