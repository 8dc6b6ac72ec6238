package robosim.params;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.Optional;
import robosim.protocol.RobotParameters;

/**
 * Finds and reads a robot parameter file, in either form ({@code .p} or {@code .xml}; see
 * {@link RobotParametersReader}). A path that exists is read as given; a bare name such as
 * {@code p3dx}, {@code p3dx.p} or {@code p3dx.xml} is also looked for in
 * {@code testLoadFiles/robots/} under the RoboSim root ({@link #root()}). A name without an
 * extension means ARIA's {@code .p} form.
 */
public final class RobotParameterFiles {
    /** A team built from one file reads it once: see {@link ReadOnce}. */
    private static final ReadOnce<RobotParameters> LOADED = new ReadOnce<>(RobotParametersReader::read);
    private static final ReadOnce<BumperParameters> BUMPERS = new ReadOnce<>(ParameterFileReader::bumpers);
    private static final ReadOnce<Integer> SONAR_CYCLES = new ReadOnce<>(ParameterFileReader::sonarCycle);

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
        return LOADED.get(resolve(file));
    }

    /**
     * Finds a parameter file as {@link #load} does and reads its conversion factors: those of
     * {@code Section Conversion factors} for ARIA's form, ARIA's defaults with the file's
     * {@code diffConvFactor} for the XML forms, which have no other factors.
     *
     * @param file a path, or a shipped name such as {@code p3dx} or {@code p3at-sh}
     * @return the robot's conversion factors
     * @throws IllegalArgumentException if no such file is found
     * @throws robosim.params.ParameterFileException if the file breaks a rule
     */
    public static ConversionFactors conversionFactors(String file) {
        Path path = resolve(file);
        Path name = path.getFileName();
        if (name != null && name.toString().toLowerCase(java.util.Locale.ROOT).endsWith(".p")) {
            return ParameterFileReader.conversionFactors(path);
        }
        return ConversionFactors.ARIA_DEFAULTS.withDiffConvFactor(RobotParametersReader.read(path).diffConvFactor());
    }

    /**
     * The conversion factors of a subclass's ARIA model, found as ARIA finds them: the {@code .p}
     * file named after the subclass (a shipped one such as {@code p3dx.p}). This is the file an ARIA
     * program loads for a robot whose server names that subclass.
     *
     * @param subclass for example {@code p3dx}
     * @return its factors, or ARIA's defaults when there is no such file
     * @throws robosim.params.ParameterFileException if the file breaks a rule
     */
    public static ConversionFactors conversionFactorsOfSubclass(String subclass) {
        try {
            return conversionFactors(subclass + ".p");
        } catch (IllegalArgumentException noModel) {
            return ConversionFactors.ARIA_DEFAULTS;
        }
    }

    /**
     * Finds a parameter file as {@link #load} does and reads its bump rings: the bumper keys of
     * ARIA's form, ARIA's defaults (no rings) for the XML forms, which have none.
     *
     * @param file a path, or a shipped name such as {@code p3dx}
     * @return the robot's bump rings
     * @throws IllegalArgumentException if no such file is found
     * @throws robosim.params.ParameterFileException if a bumper key breaks a rule
     */
    public static BumperParameters bumpers(String file) {
        Path path = resolve(file);
        Path name = path.getFileName();
        if (name != null && name.toString().toLowerCase(java.util.Locale.ROOT).endsWith(".p")) {
            return BUMPERS.get(path);
        }
        return BumperParameters.ARIA_DEFAULTS;
    }

    /**
     * Finds a parameter file as {@link #load} does and reads its {@code SonarCycle}
     * ({@link ParameterFileReader#sonarCycle}); 0 (every step) for the XML forms.
     *
     * @param file a path, or a shipped name such as {@code p3dx}
     * @return simulated ms between sonar firings, 0 for every step
     * @throws IllegalArgumentException if no such file is found
     * @throws robosim.params.ParameterFileException if the value breaks the rule
     */
    public static int sonarCycle(String file) {
        Path path = resolve(file);
        Path name = path.getFileName();
        if (name != null && name.toString().toLowerCase(java.util.Locale.ROOT).endsWith(".p")) {
            return SONAR_CYCLES.get(path);
        }
        return 0;
    }

    /**
     * @return the RoboSim root: the system property {@code robosim.root}; else the working directory
     *         when it holds {@code testLoadFiles/robots}; else the clone RoboSim's jars were loaded
     *         from (a program run with plain {@code java} from a folder of its own); else the working
     *         directory
     */
    public static Path root() {
        return ShippedFiles.root();
    }

    /**
     * Finds a shipped parameter file by its bare name, as {@code ArRobot}, {@code env --robot} and a
     * world's {@code params} take it.
     *
     * @param name for example {@code p3dx}, {@code p3dx.p} or {@code scout.xml}: a name without an
     *             extension means ARIA's {@code .p} form; a name with a path separator is no shipped name
     * @return the file in {@code testLoadFiles/robots/} under the {@link #root()}, or empty
     */
    public static Optional<Path> shipped(String name) {
        return ShippedFiles.find(name);
    }

    /**
     * @return the names {@link #shipped} finds, sorted: each {@code .p} file's name without its
     *         extension ({@code p3dx}), each {@code .xml} file's with it ({@code p3dx.xml}); for messages
     */
    public static List<String> shippedNames() {
        return ShippedFiles.names();
    }

    /**
     * @return the folder {@link #shipped} looks in: {@code testLoadFiles/robots} under the {@link #root()}
     */
    public static Path shippedFolder() {
        return ShippedFiles.robots(root());
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
        Optional<Path> shipped = shipped(file);
        if (shipped.isPresent()) {
            return shipped.get();
        }
        throw new IllegalArgumentException("robot parameter file '" + file + "' not found (looked at "
                + given.toAbsolutePath() + " and " + shippedFolder().resolve(ShippedFiles.withExtension(file))
                .toAbsolutePath() + ")");
    }
}
