package robosim.remote;

/**
 * A message typed in the send box, checked: to one robot, to a group's members, or to every other
 * robot; text of 1 to {@value #MAX_TEXT} characters.
 *
 * @param to   who it goes to
 * @param name the robot or group, or null for everyone
 * @param text the text
 */
public record MessageDraft(To to, String name, String text) {
    /** The longest text the box sends, characters. */
    public static final int MAX_TEXT = 1000;

    /** Who a message goes to. */
    public enum To {
        /** Every other robot. */
        ALL,
        /** One robot, by name. */
        ROBOT,
        /** The members of a group. */
        GROUP
    }

    /**
     * Checks a message as typed.
     *
     * @param to   who it goes to
     * @param name the robot or group typed (ignored for {@link To#ALL})
     * @param text the text typed
     * @return the message
     * @throws IllegalArgumentException naming the field, the value and the rule
     */
    public static MessageDraft of(To to, String name, String text) {
        String n = name == null ? "" : name.trim();
        if (to != To.ALL && n.isEmpty()) {
            throw new IllegalArgumentException("no " + (to == To.ROBOT ? "robot" : "group") + " was supplied for to:"
                    + " a message to one " + (to == To.ROBOT ? "robot" : "group") + " needs its name");
        }
        if (to != To.ALL && !n.matches("[A-Za-z0-9_.-]{1,64}")) {
            throw new IllegalArgumentException("'" + n + "' was supplied for to: a name is 1 to 64 letters, digits,"
                    + " '_', '.' or '-'");
        }
        String t = text == null ? "" : text.strip();
        if (t.isEmpty() || t.length() > MAX_TEXT) {
            throw new IllegalArgumentException("a message of " + t.length() + " characters was supplied: a message is 1 to "
                    + MAX_TEXT + " characters");
        }
        return new MessageDraft(to, to == To.ALL ? null : n, t);
    }

    /** @return who it goes to, in words: {@code all}, {@code robot r2}, {@code group scouts} */
    public String recipient() {
        return switch (to) {
            case ALL -> "all";
            case ROBOT -> "robot " + name;
            case GROUP -> "group " + name;
        };
    }
}
