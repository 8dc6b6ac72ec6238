package robosim.hw;

import java.util.logging.Logger;
import robosim.params.ConversionFactors;
import robosim.params.RobotParameterFiles;

/**
 * A Pioneer's conversion factors, found as ARIA finds them: in the {@code .p} parameter file named
 * after the subclass the robot server gives in its answer to SYNC2 (a shipped one such as
 * {@code p3dx.p}, or one under the RoboSim root), each factor the file leaves out taking ARIA's
 * default. A subclass without a file takes ARIA's defaults.
 */
final class PioneerFactors {
    private static final Logger LOG = Logger.getLogger(PioneerFactors.class.getName());

    private PioneerFactors() {
    }

    /**
     * @param subclass the robot server's subclass, for example {@code p3dx}
     * @return the factors of {@code <subclass>.p}, or ARIA's defaults if there is no such file
     * @throws robosim.params.ParameterFileException if the file has a factor that is not a number above 0
     */
    static ConversionFactors forSubclass(String subclass) {
        try {
            return RobotParameterFiles.conversionFactors(subclass + ".p");
        } catch (IllegalArgumentException e) {
            LOG.info(() -> "no parameter file for the Pioneer subclass '" + subclass + "': ARIA's default conversion"
                    + " factors " + ConversionFactors.ARIA_DEFAULTS + " (" + e.getMessage() + ")");
            return ConversionFactors.ARIA_DEFAULTS;
        }
    }
}
