package robosim.protocol;

/**
 * The Environment's answer to a {@link ControlRequest}: what it did, or why it refused.
 *
 * @param id   the request's id
 * @param ok   true if the request was carried out, false if it was refused (the run is then unchanged)
 * @param text what was done (for example "paused after step 42") or the reason for the refusal
 */
public record ControlReply(long id, boolean ok, String text) implements Message {
}
