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
    /** The system property that sets {@link #connectTimeoutMs} of {@link #defaults()}, in ms. */
    public static final String CONNECT_TIMEOUT_PROPERTY = "robosim.connectTimeoutMs";
    /**
     * The connect timeout when {@value #CONNECT_TIMEOUT_PROPERTY} is unset, ms: long enough for an
     * Environment started after its robots to come up on a busy machine, where a JVM's start may
     * take many seconds.
     */
    public static final long DEFAULT_CONNECT_TIMEOUT_MS = 60_000;

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
     * @return {@value #DEFAULT_CONNECT_TIMEOUT_MS} ms to connect (or what the system property
     *         {@value #CONNECT_TIMEOUT_PROPERTY} says), the Environment lost after
     *         {@value #DEFAULT_LOST_AFTER_MS} ms of silence (or what the system property
     *         {@value #LOST_AFTER_PROPERTY} says), a warning after 5 s without a yield
     * @throws IllegalArgumentException if a system property is not a whole number of ms above 0
     */
    public static HardwareOptions defaults() {
        return new HardwareOptions(configuredMs(CONNECT_TIMEOUT_PROPERTY, DEFAULT_CONNECT_TIMEOUT_MS),
                configuredLostAfterMs(), 5_000);
    }

    /**
     * @return the lost time the system property {@value #LOST_AFTER_PROPERTY} sets, or
     *         {@value #DEFAULT_LOST_AFTER_MS} if it is unset
     * @throws IllegalArgumentException if it is not a whole number of ms above 0
     */
    public static long configuredLostAfterMs() {
        return configuredMs(LOST_AFTER_PROPERTY, DEFAULT_LOST_AFTER_MS);
    }

    private static long configuredMs(String property, long unset) {
        String value = System.getProperty(property);
        if (value == null) {
            return unset;
        }
        try {
            long ms = Long.parseLong(value.trim());
            if (ms > 0 && ms <= Integer.MAX_VALUE) {
                return ms;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new IllegalArgumentException("'" + value + "' was supplied for the system property " + property
                + ": it is a whole number of ms, 1 to " + Integer.MAX_VALUE);
    }
}
