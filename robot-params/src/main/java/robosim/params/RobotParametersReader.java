package robosim.params;

import robosim.protocol.RobotParameters;

import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Reads a robot parameter file in either of its forms, chosen by the file's extension:
 * {@code .p} is ARIA's form ({@link ParameterFileReader}), {@code .xml} the original RoboSim's
 * ({@link XmlParameterFileReader}). Both give the same record for the same robot.
 */
public final class RobotParametersReader {
    private RobotParametersReader() {
    }

    /**
     * Reads a parameter file, choosing the reader by the extension (in any case).
     *
     * @param file a {@code .p} or {@code .xml} file
     * @return the robot's parameters
     * @throws ParameterFileException naming the file, the line and the rule when the file is broken,
     *                                or naming the file and the known extensions when its extension
     *                                is neither
     * @throws UncheckedIOException   when the file cannot be read
     */
    public static RobotParameters read(Path file) {
        Path name = file.getFileName();
        String lower = name == null ? "" : name.toString().toLowerCase(Locale.ROOT);
        if (lower.endsWith(".p")) {
            return ParameterFileReader.read(file);
        }
        if (lower.endsWith(".xml")) {
            return XmlParameterFileReader.read(file);
        }
        throw new ParameterFileException(file, 0,
                "not a robot parameter file: the known extensions are .p (ARIA's form) and .xml (RoboSim's form)");
    }
}
