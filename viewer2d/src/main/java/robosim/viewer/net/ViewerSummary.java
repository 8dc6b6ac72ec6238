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
    /** @return the summary in words: {@code world maze-small, 120 snapshots up to step 119; ended: done: ...} */
    public String describe() {
        return "world " + world + ", " + snapshotsReceived + " snapshot" + (snapshotsReceived == 1 ? "" : "s")
                + (lastStep >= 0 ? " up to step " + lastStep : "") + "; ended: " + endReason;
    }
}
