package robosim.scout;

/**
 * The Nomad client library's units against RoboSim's: distances in 1/10 inch (2.54 mm), angles in
 * 1/10 degree, headings in 1/10 degree from 0 to 3599, sonar ranges in whole inches from 0 to 255.
 * Conversions to the Nomad's integers round to the nearest value, halves up ({@link Math#round}).
 */
public final class NomadUnits {
    /** Millimetres in 1/10 inch. */
    public static final double MM_PER_TENTH_INCH = 2.54;
    /** Millimetres in an inch. */
    public static final double MM_PER_INCH = 25.4;
    /** The longest sonar range the Nomad reports, inches. */
    public static final long MAX_SONAR_INCHES = 255;
    /** A full turn in 1/10 degree. */
    public static final long FULL_TURN = 3600;

    private NomadUnits() {
    }

    /**
     * @param mm a distance (or a velocity in mm/s, an acceleration in mm/s²)
     * @return the same in 1/10 inch (1/10 in/s, 1/10 in/s²), rounded
     */
    public static long mmToTenthInch(double mm) {
        return Math.round(mm / MM_PER_TENTH_INCH);
    }

    /**
     * @param tenthInch a distance in 1/10 inch (or a velocity, an acceleration)
     * @return the same in mm (mm/s, mm/s²)
     */
    public static double tenthInchToMm(long tenthInch) {
        return tenthInch * MM_PER_TENTH_INCH;
    }

    /**
     * @param degrees an angle (or an angular velocity, an acceleration)
     * @return the same in 1/10 degree, rounded
     */
    public static long degToTenthDeg(double degrees) {
        return Math.round(degrees * 10);
    }

    /**
     * @param tenthDeg an angle in 1/10 degree (or an angular velocity, an acceleration)
     * @return the same in degrees
     */
    public static double tenthDegToDeg(long tenthDeg) {
        return tenthDeg / 10.0;
    }

    /**
     * @param degrees a heading, any value, counter-clockwise positive
     * @return the Nomad's heading: 1/10 degree, rounded, from 0 to 3599
     */
    public static long headingToTenthDeg(double degrees) {
        return Math.floorMod(degToTenthDeg(degrees), FULL_TURN);
    }

    /**
     * @param mm a sonar range
     * @return the Nomad's sonar reading: whole inches, rounded, clamped to 0..255
     */
    public static long sonarMmToInches(double mm) {
        return Math.max(0, Math.min(MAX_SONAR_INCHES, Math.round(mm / MM_PER_INCH)));
    }

    /**
     * @param inches a sonar reading in whole inches
     * @return the range in mm
     */
    public static double inchesToMm(long inches) {
        return inches * MM_PER_INCH;
    }
}
