package robosim.params;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

/**
 * The sonar ring a robot's class and subclass imply, for a file in the original RoboSim layout
 * that leaves its {@code <sonar>} section out (the manual's example has it in a comment): the
 * units of the robot's model, the {@code .p} file named after the subclass beside the file, or
 * else the shipped one in {@code testLoadFiles/robots/}.
 */
final class SonarDefaults {
    private SonarDefaults() {
    }

    /**
     * @param file       the file that gives no sonar units
     * @param line       the line of its {@code <subclass>} (or {@code <params>}), for messages
     * @param robotClass the file's class
     * @param subclass   the file's subclass
     * @return the model's sonar units
     * @throws ParameterFileException naming the file, line and subclass when no model is known, or
     *                                when the model is of another class
     */
    static List<SonarUnit> of(Path file, int line, String robotClass, String subclass) {
        Path model = model(file, subclass);
        if (model == null) {
            throw new ParameterFileException(file, line, "the file gives no sonar units and there is no model of subclass '"
                    + subclass + "' to take them from (looked for " + subclass + ".p beside the file and in "
                    + "testLoadFiles/robots)");
        }
        RobotParameters p = ParameterFileReader.read(model);
        if (!p.robotClass().equalsIgnoreCase(robotClass)) {
            throw new ParameterFileException(file, line, "the file gives no sonar units and the model of subclass '"
                    + subclass + "' (" + model + ") is of class " + p.robotClass() + ", not " + robotClass);
        }
        return p.sonarUnits();
    }

    private static Path model(Path file, String subclass) {
        // a subclass is a name, not a path: one with a separator or dots could reach outside
        if (!subclass.matches("[A-Za-z0-9_+-]+")) {
            return null;
        }
        Path dir = file.toAbsolutePath().getParent();
        Path beside = dir == null ? null : dir.resolve(subclass + ".p");
        if (beside != null && Files.isRegularFile(beside)) {
            return beside;
        }
        Path shipped = RobotParameterFiles.root().resolve("testLoadFiles").resolve("robots").resolve(subclass + ".p");
        return Files.isRegularFile(shipped) ? shipped : null;
    }
}
