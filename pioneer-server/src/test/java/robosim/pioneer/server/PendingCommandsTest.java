package robosim.pioneer.server;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;

/** The commands that wait for a robot's next step: the latest of each kind, in the order they last came. */
class PendingCommandsTest {
    @Test
    void aStreamOfCommandsLeavesTheLatestOfEachKindInTheOrderTheyLastCame() {
        PendingCommands p = new PendingCommands();
        for (int v = 0; v < 1000; v++) {
            p.add(new Command.SetVel(v));
            p.add(new Command.SetRotVel(-v));
        }
        p.add(new Command.SetMotors(true));
        p.add(new Command.SetVel(200));
        assertEquals(List.of(new Command.SetRotVel(-999), new Command.SetMotors(true), new Command.SetVel(200)),
                p.drain());
        assertEquals(0, p.size(), "drained");
    }

    @Test
    void aStopAfterAVelocityStopsAndAVelocityAfterAStopMoves() {
        PendingCommands p = new PendingCommands();
        p.add(new Command.SetVel(200));
        p.add(new Command.Stop());
        assertEquals(List.of(new Command.SetVel(200), new Command.Stop()), p.drain());
        p.add(new Command.Stop());
        p.add(new Command.SetVel(100));
        assertEquals(List.of(new Command.Stop(), new Command.SetVel(100)), p.drain());
    }

    @Test
    void eachDriveLimitIsAKindOfItsOwn() {
        PendingCommands p = new PendingCommands();
        p.add(new Command.SetDriveLimit(Command.DriveLimit.TRANS_ACCEL, 300));
        p.add(new Command.SetDriveLimit(Command.DriveLimit.TRANS_DECEL, 400));
        p.add(new Command.SetDriveLimit(Command.DriveLimit.TRANS_ACCEL, 500));
        assertEquals(List.of(new Command.SetDriveLimit(Command.DriveLimit.TRANS_DECEL, 400),
                new Command.SetDriveLimit(Command.DriveLimit.TRANS_ACCEL, 500)), p.drain());
    }
}
