package robosim.env.world;

import java.util.Locale;

/**
 * When a run ends of itself, from the world file's {@code <end when=... steps=...>}. Whatever the
 * rule, {@code env --steps} and a control client's {@code stop} end it too.
 *
 * @param when  the condition
 * @param steps the step after which the run ends whatever else happens; 0 for no such limit
 *              (required by {@link When#STEPS})
 */
public record EndRule(When when, long steps) {
    /** The rule of a world without {@code <end>}: every robot gone, or the gold found. */
    public static final EndRule DEFAULT = new EndRule(When.DEFAULT, 0);

    /** The conditions a world file may name. */
    public enum When {
        /** No {@code <end>}: the run ends when every robot has gone or when the gold is found. */
        DEFAULT,
        /** {@code all-left}: when every robot has gone (and only then, the gold found or not). */
        ALL_LEFT,
        /** {@code any-left}: when the first robot goes, left, dropped or lost. */
        ANY_LEFT,
        /** {@code steps}: after {@link EndRule#steps()} steps; robots may go and come meanwhile. */
        STEPS,
        /** {@code gold}: when the gold has been found and the news has had time to reach the team. */
        GOLD;

        /** @return the word the world file uses, such as {@code all-left} */
        public String word() {
            return name().toLowerCase(Locale.ROOT).replace('_', '-');
        }
    }

    /** Checks the limit. */
    public EndRule {
        if (when == null || steps < 0 || (when == When.STEPS && steps == 0)) {
            throw new IllegalArgumentException(steps + " was supplied for steps with end " + when
                    + ": steps is 0 or more, and at least 1 when the run ends after its steps");
        }
    }

    /** @return whether the run ends when every robot has gone */
    public boolean whenAllGone() {
        return when == When.DEFAULT || when == When.ALL_LEFT;
    }

    /** @return whether the run ends when the gold is found */
    public boolean whenGoldFound() {
        return when == When.DEFAULT || when == When.GOLD;
    }
}
