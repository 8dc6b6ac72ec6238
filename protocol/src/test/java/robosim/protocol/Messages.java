package robosim.protocol;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Literal messages for the codec and snapshot tests. Every field holds a value that differs from its
 * type's default, so a field lost on the wire shows up as a difference.
 */
final class Messages {
    private Messages() {
    }

    /** The Pioneer 3 DX of docs/ARIA-SEMANTICS.md, field by field. */
    static RobotParameters p3dx() {
        return new RobotParameters("Pioneer", "p3dx", 250, 425, 210, 301, 2200, 500, 300, 300, 100, 100,
                0.0056, 5000, List.of(
                        new SonarUnit(0, 69, 136, 90),
                        new SonarUnit(1, 114, 119, 50),
                        new SonarUnit(2, 148, 78, 30),
                        new SonarUnit(3, 166, 27, 10),
                        new SonarUnit(4, 166, -27, -10),
                        new SonarUnit(5, 148, -78, -30),
                        new SonarUnit(6, 114, -119, -50),
                        new SonarUnit(7, 69, -136, -90),
                        new SonarUnit(8, -157, -136, -90),
                        new SonarUnit(9, -203, -119, -130),
                        new SonarUnit(10, -237, -78, -150),
                        new SonarUnit(11, -255, -27, -170),
                        new SonarUnit(12, -255, 27, 170),
                        new SonarUnit(13, -237, 78, 150),
                        new SonarUnit(14, -203, 119, 130),
                        new SonarUnit(15, -157, 136, 90)));
    }

    /** A state whose time does not fit in an int, with a reading in every one of 16 sonars. */
    static RobotState state() {
        return RobotStates.of(41, 3_000_000_123L, 1234.5, -678.25, 179.5, 350.0, -12.5, 337.5, 362.5, true,
                new int[] {5000, 4890, 2311, 742, 739, 2200, 5000, 4999, 3010, 2875, 118, 101, 4400, 4301, 650, 640},
                3, new int[] {8000, 7999, 1234, 20}, new HeatReading(12.5, -30.25, 2200),
                List.of(new MessageDelivery("robot2", Command.Addressing.GROUP, "explorers", "text", "hello ✓", 40, 7)),
                List.of("message 3 is addressed to 'nobody', but there is no robot of that name"), 0b100001);
    }

    /** A run secret, as {@link RunSecret#create} makes them. */
    static final String SECRET = "q3Zt0m9B1x-F_kLr8cVwYh2NsPe4JdUa6GiOoT5bXyE";

    static RobotHello robotHello() {
        return new RobotHello("robot1", "pioneer", p3dx(), SECRET);
    }

    static Welcome welcome() {
        Map<String, String> properties = new LinkedHashMap<>();
        properties.put("cellSize", "1000");
        properties.put("goal.name", "gold ✓");
        return new Welcome("robot1", 100, state(), properties, -7_654_321_987L);
    }

    static TimeStep timeStep() {
        return new TimeStep(42, 3_000_000_223L, state());
    }

    /** Requests holding one command of every subtype, in a fixed order. */
    static RobotRequests robotRequests() {
        return new RobotRequests(42, List.of(
                new Command.SetVel(300.5),
                new Command.SetRotVel(-15.25),
                new Command.SetVel2(120, 180),
                new Command.Move(-750),
                new Command.SetHeading(135),
                new Command.SetDeltaHeading(-45.5),
                new Command.Stop(),
                new Command.SetMaxTransVel(900),
                new Command.SetMaxRotVel(90),
                new Command.SetSonar(false),
                new Command.ConfigureLaser(true, 0.5, 8000),
                new Command.ConfigureHeatSensor(true, 60, 4000),
                new Command.SendMessage(5, Command.Addressing.ROBOT, "robot2", "text", "hi"),
                new Command.JoinGroup("explorers"),
                new Command.LeaveGroup("explorers"),
                new Command.ReportFound("gold"),
                new Command.Say("found it"),
                new Command.MoveWheels(-120.5, 300),
                new Command.SetAccel(250, 60),
                new Command.SetDriveLimit(Command.DriveLimit.TRANS_DECEL, 400),
                new Command.SetTruePose(-1500, 2500, 90),
                new Command.ResetToStart(),
                new Command.ReportTruePose(true),
                new Command.Gripper(Command.Gripper.LIFT_CARRY, -25),
                new Command.ConfigurePtz(PtzModel.SONY, 420),
                new Command.AimPtz(-12.5, 4, 300),
                new Command.TrackColors(true),
                new Command.BindChannel(3, "#00ff7f"),
                new Command.SetSonarCycle(40),
                new Command.SetMotors(true),
                new Command.Draw("frontier", List.of(new Figure(Figure.CELLS, "red", new double[] {0, 0, 500, 500}))),
                new Command.ReportMetric("cellsExplored", 37.5),
                new Command.EndRun("gold found ✓")));
    }

    static ViewerHello viewerHello() {
        return new ViewerHello("viewer-Ω");
    }

    static WorldDescription worldDescription() {
        return new WorldDescription("arena", 20000, 15000, 100,
                List.of(new WorldDescription.Obstacle(new double[] {0, 0, 20000, 0, 20000, 10, 0, 10}, 500),
                        new WorldDescription.Obstacle(new double[] {4000.5, 3000, 5000, 3000, 4500, 3866.25}, 250)),
                List.of(new WorldDescription.RobotInfo("robot1", "pioneer", p3dx())),
                List.of(new WorldDescription.HeatSource(7000, 3000.5, 40)));
    }

    static Snapshot snapshot() {
        return new Snapshot(42, 4200, List.of(
                new Snapshot.RobotView("robot1", 1234.5, -678.25, 179.5, true, true,
                        new int[] {5000, 4890, 2311, 742, 739, 2200, 5000, 4999}),
                new Snapshot.RobotView("robot2", 8000, 9000.75, -90, false, false, new int[] {118, 101},
                        8010.5, 8990, -89.5, new int[] {3000, 2999, 2998}, 0.5, -120.5, 3.25)),
                List.of(new MessageDelivery("robot1", Command.Addressing.ALL, "*", "text", "gold!", 42, 9)),
                List.of(new Snapshot.Said("robot2", "hello")))
                .withRunEvents(List.of(new Snapshot.Metric("robot1", "cellsExplored", 37.5),
                        new Snapshot.Metric("robot2", "gold.distance", -0.25)),
                        new Snapshot.EndRequest("robot1", 42, "gold found ✓"));
    }

    static Bye bye() {
        return new Bye("done");
    }

    /** One message of every type. */
    static CommsUpdate commsUpdate() {
        return new CommsUpdate(2500.5, true, null, 0.125, 1024);
    }

    static LinkHello linkHello() {
        return new LinkHello("client-7", SECRET);
    }

    static ControlHello controlHello() {
        return new ControlHello("comms", SECRET);
    }

    /** Two robots' states, the second without sonar. */
    static TimeSteps timeSteps() {
        RobotState quiet = new RobotState(41, 4100, 10, 20, -90, 0, 0, 0, 0, false, 0);
        return new TimeSteps(42, 4200, List.of(new TimeSteps.ForRobot("robot1", state()),
                new TimeSteps.ForRobot("robot2", quiet)));
    }

    /** Every command for one robot, none for the other. */
    static LinkRequests linkRequests() {
        return new LinkRequests(42, List.of(new LinkRequests.ForRobot("robot1", robotRequests().commands()),
                new LinkRequests.ForRobot("robot2", List.of())));
    }

    static KeepAlive keepAlive() {
        return new KeepAlive(42);
    }

    static ControlRequest controlRequest() {
        return new ControlRequest(7, "move", List.of("robot1", "1500", "-250.5", "90"));
    }

    static ControlReply controlReply() {
        return new ControlReply(7, false, "move: no robot named 'robot9' in world demo");
    }

    static LogLine logLine() {
        return new LogLine(42, "INFO", "robot r2 rejoined at step 43 (after step 42)");
    }

    static RunStatus runStatus() {
        return new RunStatus(7, "demo", 42, 4200, false, 1, List.of(
                new RunStatus.RobotStatus("robot1", "p3dx", "program at 127.0.0.1:40312", true, 1500, -250.5, 90,
                        300, -15.5, false, 2, 5, 3, 42),
                new RunStatus.RobotStatus("robot2", "p3at", "", false, 0, 0, 0, 0, 0, true, 0, 0, 0, 0)));
    }

    static List<Message> all() {
        return List.of(robotHello(), welcome(), timeStep(), robotRequests(), viewerHello(), worldDescription(),
                snapshot(), bye(), commsUpdate(), linkHello(), timeSteps(), linkRequests(), controlHello(),
                keepAlive(), controlRequest(), controlReply(), runStatus(), logLine());
    }
}
