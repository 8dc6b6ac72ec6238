package robosim.params;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import robosim.protocol.RobotParameters;

/**
 * Finds and reads a robot parameter file, in either form ({@code .p} or {@code .xml}; see
 * {@link RobotParametersReader}). A path that exists is read as given; a bare name such as
 * {@code p3dx}, {@code p3dx.p} or {@code p3dx.xml} is also looked for in
 * {@code testLoadFiles/robots/} under the RoboSim root (system property {@code robosim.root},
 * else the working directory). A name without an extension means ARIA's {@code .p} form.
 */
public final class RobotParameterFiles {
    private RobotParameterFiles() {
    }

    /**
     * Finds and reads a parameter file.
     *
     * @param file a path, or a shipped name such as {@code p3dx} or {@code scout.xml}
     * @return the robot's parameters
     * @throws IllegalArgumentException if no such file is found
     * @throws robosim.params.ParameterFileException if the file breaks a rule
     */
    public static RobotParameters load(String file) {
        return RobotParametersReader.read(resolve(file));
    }

    /**
     * Finds a parameter file and reads its conversion factors (see {@link ConversionFactors}).
     *
     * @param file a path, or a shipped name
     * @return the factors; ARIA's defaults for a file of another form
     */
    public static ConversionFactors conversionFactors(String file) {
        return ConversionFactorsReader.read(resolve(file));
    }

    /**
     * @return the RoboSim root: system property {@code robosim.root}, else the working directory
     */
    public static Path root() {
        return Paths.get(System.getProperty("robosim.root", "."));
    }

    /**
     * @param file a path, or a shipped name
     * @return the file it names
     * @throws IllegalArgumentException if no such file is found
     */
    public static Path resolve(String file) {
        Path given = Paths.get(file);
        if (Files.isRegularFile(given)) {
            return given;
        }
        String name = file.endsWith(".p") || file.endsWith(".xml") ? file : file + ".p";
        Path root = root();
        Path shipped = root.resolve("testLoadFiles").resolve("robots").resolve(name);
        if (Files.isRegularFile(shipped)) {
            return shipped;
        }
        throw new IllegalArgumentException("robot parameter file '" + file + "' not found (looked at "
                + given.toAbsolutePath() + " and " + shipped.toAbsolutePath() + ")");
    }
}
