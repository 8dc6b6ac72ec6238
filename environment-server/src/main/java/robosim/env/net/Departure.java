package robosim.env.net;

/**
 * A robot that did not run to the end of the run: it left, was dropped or was lost, at a step, for
 * a reason. The robots without one ran to the end.
 *
 * @param robot  the robot
 * @param kind   how it went
 * @param step   the step open when it went (its requests were awaited for that step)
 * @param reason why: its bye's reason, the rule it broke, or what became of its connection
 */
public record Departure(String robot, Kind kind, long step, String reason) {
    /** How a robot can go before the end of the run. */
    public enum Kind {
        /** It said bye: its program disconnected or ended. */
        LEFT("left"),
        /** The Environment took it out: it broke a rule or missed the step deadline. */
        DROPPED("dropped"),
        /** Its connection closed without a bye, or broke. */
        LOST("lost");

        private final String word;

        Kind(String word) {
            this.word = word;
        }

        /** @return the word the run report uses: left, dropped or lost */
        public String word() {
            return word;
        }
    }

    /** @return how the run report says it, for example {@code lost at step 7: the connection closed without a bye} */
    public String describe() {
        return kind.word() + " at step " + step + ": " + reason;
    }
}
