package robosim.viewer;

/**
 * What a {@link ViewerClient} run saw.
 *
 * @param world          the name of the world it attached to
 * @param framesReceived the {@code ViewerFrame}s received
 * @param framesWritten  the frames rendered and handed to the sink
 * @param lastStep       the step of the last frame received, or -1 if none came
 * @param endReason      why the run ended: the {@code Bye}'s reason, or {@code "end of stream"}
 */
public record ViewerSummary(String world, long framesReceived, long framesWritten, long lastStep,
                            String endReason) {
}
