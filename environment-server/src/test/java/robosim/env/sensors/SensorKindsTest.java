package robosim.env.sensors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import robosim.env.world.Noise;
import robosim.params.RobotParameterFiles;
import robosim.protocol.Command;
import robosim.protocol.GripperState;
import robosim.protocol.StatePart;
import robosim.protocol.StateParts;
import robosim.protocol.TruePose;

/** Every sensor setting has exactly one sensor, and every part of the state has one maker. */
class SensorKindsTest {
    private static List<Sensor> sensors() {
        SensorSetup setup = new SensorSetup(RobotParameterFiles.load("p3dx"), Noise.NONE, new SplittableRandom(1));
        List<Sensor> made = new ArrayList<>();
        for (var kind : SensorKinds.ALL) {
            made.add(kind.apply(setup));
        }
        return made;
    }

    @Test
    void eachSensorSettingIsTakenByExactlyOneSensor() {
        List<Sensor> sensors = sensors();
        int settings = 0;
        for (Class<?> type : Command.SensorSetting.class.getPermittedSubclasses()) {
            List<String> takers = new ArrayList<>();
            Command.SensorSetting setting = example(type);
            for (Sensor s : sensors) {
                if (s.configures(setting)) {
                    takers.add(s.getClass().getSimpleName());
                }
            }
            assertEquals(1, takers.size(), type.getSimpleName() + " is taken by " + takers);
            settings++;
        }
        assertEquals(9, settings, "the settings there are: give a new one an example below");
    }

    @Test
    void everyPartOfTheStateButTheGrippersHasASensorThatReportsIt() {
        List<Sensor> sensors = sensors();
        for (Sensor s : sensors) {
            for (Class<?> type : Command.SensorSetting.class.getPermittedSubclasses()) {
                Command.SensorSetting on = example(type);
                if (s.configures(on)) {
                    s.configure(on);
                }
            }
        }
        StateParts parts = StateParts.NONE;
        for (Sensor s : sensors) {
            parts = s.report(parts, new TruePose(1, 2, 3));
        }
        for (StatePart<?> part : StateParts.ALL) {
            if (part != GripperState.PART) { // the gripper is an accessory, which the simulation's grippers report
                // the heat sensor reports once it has sensed
                assertTrue(parts.get(part) != null || part.name().equals("heat"),
                        part.name() + " has no sensor reporting it: " + parts);
            }
        }
    }

    /** A setting of each type that switches its sensor on. */
    private static Command.SensorSetting example(Class<?> type) {
        return switch (type.getSimpleName()) {
            case "SetSonar" -> new Command.SetSonar(true);
            case "ConfigureLaser" -> new Command.ConfigureLaser(true, 1, 8000);
            case "ConfigureHeatSensor" -> new Command.ConfigureHeatSensor(true, 90, 5000);
            case "ReportTruePose" -> new Command.ReportTruePose(true);
            case "ConfigurePtz" -> new Command.ConfigurePtz(robosim.protocol.PtzModel.VCC4, 300);
            case "AimPtz" -> new Command.AimPtz(10, 0, 0);
            case "TrackColors" -> new Command.TrackColors(true);
            case "BindChannel" -> new Command.BindChannel(1, "red");
            case "SetSonarCycle" -> new Command.SetSonarCycle(40);
            default -> throw new AssertionError("no example of " + type.getSimpleName() + ": add one here");
        };
    }
}
