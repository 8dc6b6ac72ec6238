package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import robosim.env.world.World;
import robosim.protocol.Command;
import robosim.protocol.Figure;
import robosim.protocol.LaserReading;

/**
 * Every kind of command a robot can send reaches a handler in the core: a command record added to
 * {@link Command} without its handler fails here, not in a robot's run.
 */
class EveryCommandHandledTest {
    /** One of each command record, in the order a robot might send them. */
    private static final List<Command> ONE_OF_EACH = List.of(
            new Command.SetVel(100), new Command.SetRotVel(5), new Command.SetVel2(50, 60),
            new Command.Move(200), new Command.SetHeading(30), new Command.SetDeltaHeading(-10),
            new Command.Stop(), new Command.SetMaxTransVel(500), new Command.SetMaxRotVel(40),
            new Command.MoveWheels(10, 20), new Command.SetAccel(300, 100),
            new Command.SetSonar(true), new Command.ConfigureLaser(true, 1, 8000),
            new Command.ConfigureHeatSensor(true, 90, 5000),
            new Command.SendMessage(1, Command.Addressing.ALL, null, "text", "hi"),
            new Command.JoinGroup("team"), new Command.LeaveGroup("team"),
            new Command.Say("hello"), new Command.ReportFound("gold"),
            new Command.SetDriveLimit(Command.DriveLimit.ROT_DECEL, 50), new Command.ReportTruePose(true),
            new Command.SetTruePose(5000, 6000, 90), new Command.ResetToStart(),
            new Command.Gripper(Command.Gripper.GRIP_CLOSE),
            new Command.ConfigurePtz(robosim.protocol.PtzModel.VCC4, 300), new Command.AimPtz(10, 5, 100),
            new Command.TrackColors(true), new Command.BindChannel(9, "#123456"),
            new Command.SetSonarCycle(40), new Command.SetMotors(true),
            new Command.Draw("map", List.of(new Figure(Figure.DOTS, "", new double[] {1, 2}))),
            new Command.ReportMetric("cells", 3), new Command.EndRun("done"));

    @Test
    void theListHoldsEveryCommandRecordOfEveryGroup() {
        Set<String> records = new TreeSet<>();
        for (Class<?> group : Command.class.getPermittedSubclasses()) {
            assertTrue(group.isInterface(), group + " is a group of commands");
            for (Class<?> record : group.getPermittedSubclasses()) {
                records.add(record.getSimpleName());
            }
        }
        Set<String> listed = new TreeSet<>();
        for (Command c : ONE_OF_EACH) {
            listed.add(c.getClass().getSimpleName());
        }
        assertEquals(records, listed);
    }

    @Test
    void aStepWithOneOfEachCommandRunsThemAll() {
        World w = Worlds.world(10000, 10000, List.of(), Worlds.robot("a", 5000, 5000, 0),
                Worlds.robot("b", 2000, 2000, 0));
        Simulation sim = new Simulation(w);
        sim.setConnected("a", true);
        sim.setConnected("b", true);
        List<Command> commands = new ArrayList<>(ONE_OF_EACH);
        assertDoesNotThrow(() -> sim.step(Map.of("a", commands)));
        assertEquals("hello", sim.snapshot().said().get(0).text());
        assertEquals(1, sim.snapshot().messages().size(), "the broadcast was sent");
        assertTrue(sim.state("a").get(LaserReading.PART).ranges().length > 0, "the laser is on");
    }
}
