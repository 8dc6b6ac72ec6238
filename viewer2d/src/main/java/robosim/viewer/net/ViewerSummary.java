package robosim.viewer.net;

/**
 * What a {@link ViewerClient} run saw.
 *
 * @param world          the name of the world it attached to
 * @param snapshotsReceived the {@code Snapshot}s received
 * @param lastStep       the step of the last snapshot received, or -1 if none came
 * @param endReason      why the run ended: the {@code Bye}'s reason, or {@code "end of stream"}
 */
public record ViewerSummary(String world, long snapshotsReceived, long lastStep,
                            String endReason) {
    /**
     * @return the summary in words, as a log line says it, for example {@code world 'small-maze',
     *         601 snapshots up to step 600, ended: done: step limit 600 reached}
     */
    public String describe() {
        String steps = snapshotsReceived == 0 ? "no snapshot"
                : snapshotsReceived + (snapshotsReceived == 1 ? " snapshot" : " snapshots") + " up to step " + lastStep;
        return (world == null ? "no world" : "world '" + world + "'") + ", " + steps + ", ended: " + endReason;
    }
}
