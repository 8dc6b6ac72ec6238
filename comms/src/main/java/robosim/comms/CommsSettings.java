package robosim.comms;

/**
 * How messages travel between robots. Changeable while a run goes on.
 *
 * @param maxRange        the farthest a message reaches, mm, between sender and recipient as it
 *                        is delivered; 0 means no limit
 * @param wallsBlock      whether a wall or obstacle between sender and recipient stops a message
 * @param latencySteps    steps between sending and delivery, at least 1 (a message sent in step
 *                        n arrives with the state after step n + latency − 1)
 * @param lossProbability the chance, 0 to 1, that a message is lost on its way to each recipient,
 *                        drawn from the run's seed
 * @param maxMessageBytes the largest payload accepted, in UTF-8 bytes
 */
public record CommsSettings(double maxRange, boolean wallsBlock, int latencySteps, double lossProbability,
                            int maxMessageBytes) {

    /** Unlimited range, walls do not block, delivered after one step, nothing lost, 64 KiB. */
    public static final CommsSettings DEFAULT = new CommsSettings(0, false, 1, 0, 65536);

    /** Checks every figure; a bad one is named with the rule it breaks. */
    public CommsSettings {
        if (!(maxRange >= 0) || Double.isInfinite(maxRange)) {
            throw new IllegalArgumentException(maxRange + " was supplied for maxRange: it must be 0 (no limit) or more");
        }
        if (latencySteps < 1) {
            throw new IllegalArgumentException(latencySteps + " was supplied for latencySteps: it must be at least 1");
        }
        if (!(lossProbability >= 0 && lossProbability <= 1)) {
            throw new IllegalArgumentException(lossProbability + " was supplied for lossProbability: it must be from 0 to 1");
        }
        if (maxMessageBytes < 1) {
            throw new IllegalArgumentException(maxMessageBytes + " was supplied for maxMessageBytes: it must be at least 1");
        }
    }

    /**
     * @return the settings in words, as a log line or a user reads them: {@code range 5000 mm, walls
     *         block, latency 1 step, loss 0.100, messages up to 65536 bytes}
     */
    public String describe() {
        return String.format(java.util.Locale.ROOT, "range %s, walls %s, latency %d step%s, loss %.3f, messages up to %d bytes",
                maxRange == 0 ? "unlimited" : String.format(java.util.Locale.ROOT, "%.0f mm", maxRange),
                wallsBlock ? "block" : "do not block", latencySteps, latencySteps == 1 ? "" : "s", lossProbability,
                maxMessageBytes);
    }
}
