package robosim.protocol;

import java.util.Set;

/**
 * One line of the Environment's log, sent to a control client that asked to follow it (a
 * {@link ControlRequest} with op {@code log}), so that a ControlPanel attached to an Environment it
 * did not start can show what the Environment says: robots joining and leaving, refusals, control
 * requests carried out.
 *
 * @param step  the last step run when the line was logged
 * @param level {@code SEVERE}, {@code WARNING} or {@code INFO}
 * @param text  the line, at most {@value #MAX_TEXT} characters
 */
public record LogLine(long step, String level, String text) implements Message {
    /** The longest line sent; a longer one is cut by the Environment. */
    public static final int MAX_TEXT = 4000;
    /** The levels a line may have: the Environment forwards INFO and above. */
    public static final Set<String> LEVELS = Set.of("SEVERE", "WARNING", "INFO");

    /**
     * Checks every value.
     *
     * @throws IllegalArgumentException naming the value and the rule
     */
    public LogLine {
        if (step < 0) {
            throw new IllegalArgumentException("a log line's step is 0 or more, got " + step);
        }
        if (!LEVELS.contains(level)) {
            throw new IllegalArgumentException("a log line's level is SEVERE, WARNING or INFO, got "
                    + RobotHello.quoted(level));
        }
        text = text == null ? "" : text;
        if (text.length() > MAX_TEXT) {
            throw new IllegalArgumentException("a log line is at most " + MAX_TEXT + " characters, got " + text.length());
        }
    }
}
