package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonInclude;

/**
 * The last message of a connection, from either side; on a connection shared by many robots (see
 * {@link LinkHello}) it may instead end one robot's part in the run.
 *
 * @param reason why the connection, or the robot's part, ends; {@code "done"} for an orderly end
 * @param robot  on a shared connection, the robot that leaves, is refused or is dropped; null for the
 *               whole connection (and then absent on the wire, as before shared links)
 */
public record Bye(String reason, @JsonInclude(JsonInclude.Include.NON_NULL) String robot) implements Message {
    /**
     * The last message of a whole connection.
     *
     * @param reason why it ends
     */
    public Bye(String reason) {
        this(reason, null);
    }
}
