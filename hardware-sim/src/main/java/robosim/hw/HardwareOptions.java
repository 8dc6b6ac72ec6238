package robosim.hw;

/**
 * Timeouts of a robot's link.
 *
 * @param connectTimeoutMs longest wait to connect and to be welcomed
 * @param lostAfterMs      longest silence of the Environment, neither a step nor a keep-alive, before
 *                         the robot declares it lost and its part in the run ends (the Environment
 *                         sends a keep-alive after a second without anything else, so a few seconds
 *                         are plenty)
 * @param yieldWarningMs   how long the robot's code may run without yielding before a warning
 */
public record HardwareOptions(long connectTimeoutMs, long lostAfterMs, long yieldWarningMs) {
    /** The system property that sets {@link #lostAfterMs} of {@link #defaults()}, in ms. */
    public static final String LOST_AFTER_PROPERTY = "robosim.lostAfterMs";
    /** The lost time when {@value #LOST_AFTER_PROPERTY} is unset, ms. */
    public static final long DEFAULT_LOST_AFTER_MS = 10_000;

    /**
     * Checks the values.
     *
     * @throws IllegalArgumentException if a time is not positive
     */
    public HardwareOptions {
        requirePositive("connectTimeoutMs", connectTimeoutMs);
        requirePositive("lostAfterMs", lostAfterMs);
        requirePositive("yieldWarningMs", yieldWarningMs);
    }

    private static void requirePositive(String name, long ms) {
        if (ms <= 0 || ms > Integer.MAX_VALUE) {
            throw new IllegalArgumentException(ms + " was supplied for " + name + ": it is 1 to " + Integer.MAX_VALUE
                    + " ms");
        }
    }

    /**
     * @return 10 s to connect, the Environment lost after {@value #DEFAULT_LOST_AFTER_MS} ms of
     *         silence (or what the system property {@value #LOST_AFTER_PROPERTY} says), a warning after
     *         5 s without a yield
     * @throws IllegalArgumentException if the system property is not a whole number of ms above 0
     */
    public static HardwareOptions defaults() {
        return new HardwareOptions(10_000, configuredLostAfterMs(), 5_000);
    }

    /**
     * @return the lost time the system property {@value #LOST_AFTER_PROPERTY} sets, or
     *         {@value #DEFAULT_LOST_AFTER_MS} if it is unset
     * @throws IllegalArgumentException if it is not a whole number of ms above 0
     */
    public static long configuredLostAfterMs() {
        String value = System.getProperty(LOST_AFTER_PROPERTY);
        if (value == null) {
            return DEFAULT_LOST_AFTER_MS;
        }
        try {
            long ms = Long.parseLong(value.trim());
            if (ms > 0 && ms <= Integer.MAX_VALUE) {
                return ms;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new IllegalArgumentException("'" + value + "' was supplied for the system property " + LOST_AFTER_PROPERTY
                + ": it is a whole number of ms, 1 to " + Integer.MAX_VALUE);
    }
}
