package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonInclude;

/**
 * The last message of a connection, from either side; on a connection shared by many robots (see
 * {@link LinkHello}) it may instead end one robot's part in the run.
 *
 * <p>From the Environment the reason says how the robot's part ended: {@value #DONE} and why for
 * the end of the run (the step limit, the gold found, ...); {@value #REFUSED} and the rule for a
 * hello it refused; {@value #GOODBYE} to confirm a robot's own bye; any other reason drops the robot
 * from the run (a broken rule, a missed step deadline) and says why.
 *
 * @param reason why the connection, or the robot's part, ends
 * @param robot  on a shared connection, the robot that leaves, is refused or is dropped; null for the
 *               whole connection (and then absent on the wire, as before shared links)
 */
public record Bye(String reason, @JsonInclude(JsonInclude.Include.NON_NULL) String robot) implements Message {
    /** How the reason of the Environment's bye starts when the run has ended. */
    public static final String DONE = "done: ";
    /** How the reason of the Environment's bye starts when it refuses a robot's hello. */
    public static final String REFUSED = "refused: ";
    /** The Environment's answer to a robot that said bye. */
    public static final String GOODBYE = "goodbye";

    /**
     * The last message of a whole connection.
     *
     * @param reason why it ends
     */
    public Bye(String reason) {
        this(reason, null);
    }
}
