package robosim.viewer.replay;

/**
 * Which steps of a recording to replay.
 *
 * @param from the first step drawn, at least 0
 * @param to   the last step drawn, at least {@code from}; {@link Long#MAX_VALUE} for the end
 */
public record ReplayRange(long from, long to) {
    /** Every step. */
    public static final ReplayRange ALL = new ReplayRange(0, Long.MAX_VALUE);

    /**
     * Checks the bounds.
     *
     * @param from first step
     * @param to   last step
     * @throws IllegalArgumentException naming the bad value and the rule
     */
    public ReplayRange {
        if (from < 0) {
            throw new IllegalArgumentException(from + " was supplied for --from: it must be at least 0");
        }
        if (to < from) {
            throw new IllegalArgumentException(to + " was supplied for --to: it must be at least --from (" + from + ")");
        }
    }

    /**
     * @param step a step
     * @return whether it is in the range
     */
    public boolean contains(long step) {
        return step >= from && step <= to;
    }
}
