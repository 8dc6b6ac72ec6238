package robosim.params;

/**
 * A robot's conversion factors from its ARIA parameter file: how the Pioneer protocol's units map
 * to mm, mm/s and radians.
 *
 * @param angleConvFactor radians per heading unit
 * @param distConvFactor  mm per position unit
 * @param velConvFactor   mm/s per velocity unit
 * @param rangeConvFactor mm per sonar range unit
 * @param diffConvFactor  rad/s per mm/s of wheel-speed difference
 * @param vel2Divisor     mm/s per VEL2 unit
 */
public record ConversionFactors(double angleConvFactor, double distConvFactor, double velConvFactor,
                                double rangeConvFactor, double diffConvFactor, double vel2Divisor) {
    /** ARIA's defaults. */
    public static final ConversionFactors ARIA_DEFAULTS = new ConversionFactors(0.001534, 1, 1, 1, 0.0056, 20);
}
