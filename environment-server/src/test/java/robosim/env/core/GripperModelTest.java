package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import robosim.protocol.Command;
import robosim.protocol.GripperState;

class GripperModelTest {
    private static final double DT = 0.1;

    private static int bits(GripperModel g) {
        return g.state(0, -1).switches();
    }

    private static void run(GripperModel g, int steps) {
        for (int i = 0; i < steps; i++) {
            g.advance(DT, 0);
        }
    }

    @Test
    void startsDeployedWithPaddlesOpenAndLiftDownAtRest() {
        GripperModel g = new GripperModel();
        // open limit closed (bit 0 clear), lift at an end (bit 1 clear), paddles untriggered, nothing moving
        assertEquals(GripperState.LEFT_PADDLE_CLEAR | GripperState.RIGHT_PADDLE_CLEAR, bits(g));
        assertTrue(g.down());
    }

    @Test
    void paddlesTakeTwoSecondsToCloseAndThenBothAreTriggered() {
        GripperModel g = new GripperModel();
        g.command(new Command.Gripper(Command.Gripper.GRIP_CLOSE));
        run(g, 19);
        int between = bits(g);
        assertEquals(GripperState.PADDLES_OPEN_CLEAR | GripperState.PADDLES_MOVING
                | GripperState.LEFT_PADDLE_CLEAR | GripperState.RIGHT_PADDLE_CLEAR, between);
        run(g, 1);
        // closed: both paddle bits clear, the open bit set, no longer moving
        assertEquals(GripperState.PADDLES_OPEN_CLEAR, bits(g));
        assertEquals(1.0, g.state(0, -1).paddles());
    }

    @Test
    void liftTakesThreeSecondsToRiseAndIsBetweenMeanwhile() {
        GripperModel g = new GripperModel();
        g.command(new Command.Gripper(Command.Gripper.LIFT_UP));
        run(g, 29);
        assertEquals(GripperState.LIFT_LIMIT_CLEAR | GripperState.LIFT_MOVING,
                bits(g) & (GripperState.LIFT_LIMIT_CLEAR | GripperState.LIFT_MOVING));
        run(g, 1);
        assertEquals(0, bits(g) & (GripperState.LIFT_LIMIT_CLEAR | GripperState.LIFT_MOVING));
        assertEquals(1.0, g.state(0, -1).lift());
        assertFalse(g.down());
    }

    @Test
    void storeClosesAndRaisesAndDeployOpensAndLowers() {
        GripperModel g = new GripperModel();
        g.command(new Command.Gripper(Command.Gripper.GRIPPER_STORE));
        run(g, 30);
        GripperState stored = g.state(0, -1);
        assertEquals(1.0, stored.paddles());
        assertEquals(1.0, stored.lift());
        assertEquals(GripperState.PADDLES_OPEN_CLEAR, stored.switches());
        g.command(new Command.Gripper(Command.Gripper.GRIPPER_DEPLOY));
        run(g, 30);
        GripperState deployed = g.state(0, -1);
        assertEquals(0.0, deployed.paddles());
        assertEquals(0.0, deployed.lift());
        assertEquals(GripperState.LEFT_PADDLE_CLEAR | GripperState.RIGHT_PADDLE_CLEAR, deployed.switches());
    }

    @Test
    void stopCommandsLeaveThePaddlesAndTheLiftBetween() {
        GripperModel g = new GripperModel();
        g.command(new Command.Gripper(Command.Gripper.GRIPPER_STORE));
        run(g, 5);
        g.command(new Command.Gripper(Command.Gripper.GRIPPER_HALT));
        run(g, 5);
        GripperState s = g.state(0, -1);
        assertEquals(0.25, s.paddles(), 1e-9);
        assertEquals(0.5 / 3, s.lift(), 1e-9);
        assertEquals(0, s.switches() & (GripperState.PADDLES_MOVING | GripperState.LIFT_MOVING));
        assertEquals(GripperState.LIFT_LIMIT_CLEAR, s.switches() & GripperState.LIFT_LIMIT_CLEAR);
    }

    @Test
    void liftCarryMovesTheLiftForItsTimeOnly() {
        GripperModel g = new GripperModel();
        // 25 × 20 ms = 0.5 s of a 3 s travel
        g.command(new Command.Gripper(Command.Gripper.LIFT_CARRY, 25));
        run(g, 10);
        assertEquals(0.5 / 3, g.state(0, -1).lift(), 1e-9);
        assertEquals(0, bits(g) & GripperState.LIFT_MOVING);
        g.command(new Command.Gripper(Command.Gripper.LIFT_CARRY, -100));
        run(g, 10);
        assertTrue(g.down());
    }

    @Test
    void closingOnAnObjectStopsAtItsWidthHoldsItAndPressesForTheGraspTime() {
        GripperModel g = new GripperModel();
        g.command(new Command.Gripper(Command.Gripper.GRIP_PRESSURE, 15));
        g.command(new Command.Gripper(Command.Gripper.GRIP_CLOSE));
        // a puck of radius 38 mm stops 215 mm paddles at 1 - 76/215 closed: after 1.3 s of 2 s
        GripperModel.Event e = GripperModel.Event.NONE;
        int steps = 0;
        while (e != GripperModel.Event.GRIPPED && steps < 30) {
            e = g.advance(DT, 38);
            steps++;
        }
        assertEquals(GripperModel.Event.GRIPPED, e);
        assertEquals(13, steps);
        assertTrue(g.holding());
        assertEquals(GripperModel.closedOn(38), g.state(0, 3).paddles(), 1e-9);
        assertEquals(3, g.state(0, 3).holding());
        // both paddles triggered; still pressing for 15 × 20 ms = 0.3 s
        int pressing = g.state(0, 3).switches();
        assertEquals(0, pressing & (GripperState.LEFT_PADDLE_CLEAR | GripperState.RIGHT_PADDLE_CLEAR));
        assertEquals(GripperState.PADDLES_MOVING, pressing & GripperState.PADDLES_MOVING);
        run(g, 3);
        assertEquals(0, bits(g) & GripperState.PADDLES_MOVING);
        assertEquals(15, g.state(0, 3).graspTime());
    }

    @Test
    void openingLetsGoAtOnce() {
        GripperModel g = new GripperModel();
        g.command(new Command.Gripper(Command.Gripper.GRIP_CLOSE));
        for (int i = 0; i < 20 && !g.holding(); i++) {
            g.advance(DT, 38);
        }
        assertTrue(g.holding());
        g.command(new Command.Gripper(Command.Gripper.GRIP_OPEN));
        assertEquals(GripperModel.Event.RELEASED, g.advance(DT, 0));
        assertFalse(g.holding());
    }

    @Test
    void theBeamsBitsPassThrough() {
        GripperModel g = new GripperModel();
        int beams = GripperState.INNER_BEAM | GripperState.OUTER_BEAM;
        assertEquals(beams, g.state(beams, -1).switches() & beams);
    }
}
