package robosim.env.net;

/**
 * A robot that joined the run after it started: late, back after it went, or (in an open world) as
 * a robot the world does not name, placed at a spawn point. The robots there at the start have none.
 *
 * @param robot the robot
 * @param kind  how it joined
 * @param step  the first step it takes part in: the next step opened after it was admitted
 */
public record Join(String robot, Kind kind, long step) {
    /** How a robot can join a run under way. */
    public enum Kind {
        /** A robot the world names, connected for the first time after the run started. */
        LATE("joined late"),
        /** A robot that had gone (left, dropped or lost) and came back to its body as it was. */
        REJOINED("rejoined"),
        /** A robot the world does not name, admitted to an open world at a spawn point. */
        SPAWNED("spawned");

        private final String word;

        Kind(String word) {
            this.word = word;
        }

        /** @return the words the run report uses: joined late, rejoined or spawned */
        public String word() {
            return word;
        }
    }

    /** @return how the run report says it, for example {@code rejoined at step 12} */
    public String describe() {
        return kind.word() + " at step " + step;
    }
}
