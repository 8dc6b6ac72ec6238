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
}
