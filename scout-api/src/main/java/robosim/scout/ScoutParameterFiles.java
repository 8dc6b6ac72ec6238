package robosim.scout;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import robosim.protocol.params.RobotParameters;
import robosim.protocol.params.RobotParametersReader;

/**
 * Finds and reads a Scout's parameter file, in either form ({@code .p} or {@code .xml}). A path that
 * exists is read as given; a bare name such as {@code scout} or {@code scout.xml} is also looked for
 * in {@code testLoadFiles/robots/} under the RoboSim root (system property {@code robosim.root},
 * else the working directory). A name without an extension means the {@code .p} form.
 */
final class ScoutParameterFiles {
    /** The shipped Scout's parameter file. */
    static final String DEFAULT = "scout";

    private ScoutParameterFiles() {
    }

    static RobotParameters load(String file) {
        return RobotParametersReader.read(resolve(file));
    }

    static Path resolve(String file) {
        Path given = Paths.get(file);
        if (Files.isRegularFile(given)) {
            return given;
        }
        String name = file.endsWith(".p") || file.endsWith(".xml") ? file : file + ".p";
        Path root = Paths.get(System.getProperty("robosim.root", "."));
        Path shipped = root.resolve("testLoadFiles").resolve("robots").resolve(name);
        if (Files.isRegularFile(shipped)) {
            return shipped;
        }
        throw new IllegalArgumentException("robot parameter file '" + file + "' not found (looked at "
                + given.toAbsolutePath() + " and " + shipped.toAbsolutePath() + ")");
    }
}
