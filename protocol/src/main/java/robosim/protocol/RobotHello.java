package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonInclude;
import java.util.regex.Pattern;

/**
 * The first message of a robot's connection: who it is and what body it has.
 *
 * @param name       the robot's name, as the world file declares it
 * @param robotType  the robot's type, for example {@code pioneer}
 * @param parameters the robot's own parameters, which the Environment simulates
 * @param token      the run secret (see {@link RunSecret}), or null when the run has none or the
 *                   robot says hello on a shared link that presented it
 */
public record RobotHello(String name, String robotType, RobotParameters parameters,
                         @JsonInclude(JsonInclude.Include.NON_NULL) String token) implements Message {
    /**
     * A hello that presents no secret.
     *
     * @param name       the robot's name, as the world file declares it
     * @param robotType  the robot's type, for example {@code pioneer}
     * @param parameters the robot's own parameters, which the Environment simulates
     */
    public RobotHello(String name, String robotType, RobotParameters parameters) {
        this(name, robotType, parameters, null);
    }

    /** @return the hello with the secret masked */
    @Override
    public String toString() {
        return "RobotHello[name=" + printable(name) + ", robotType=" + robotType + ", parameters=" + parameters
                + ", token=" + RunSecret.masked(token) + "]";
    }

    /** What a robot's name may be, in a world file and on the wire: 1 to 64 letters, digits, '_', '-' or '.'. */
    public static final Pattern NAME = Pattern.compile("[A-Za-z0-9_.-]{1,64}");
    /** The rule of {@link #NAME}, in words. */
    public static final String NAME_RULE = "a robot's name is 1 to 64 letters (A-Z, a-z), digits, '_', '-' or '.'";

    /**
     * @param name a robot's name
     * @return whether it follows {@link #NAME_RULE}
     */
    public static boolean validName(String name) {
        return name != null && NAME.matcher(name).matches();
    }

    /**
     * A name as it may go into a log line or a message: every character outside printable ASCII
     * written as a backslash, u and four hex digits, and cut after 80 characters, so that a name
     * from the wire can never forge a line.
     *
     * @param name any text, or null
     * @return it, safe to print ({@code no name} for null)
     */
    public static String printable(String name) {
        return name == null ? "no name" : printable(name, 80);
    }

    /**
     * Any text from the wire as it may go into a log line, escaped as {@link #printable(String)}
     * escapes a name.
     *
     * @param text any text, or null (written {@code null})
     * @param max  the characters kept before it is cut short
     * @return it, safe to print
     */
    public static String printable(String text, int max) {
        String s = String.valueOf(text);
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < Math.min(s.length(), max); i++) {
            char c = s.charAt(i);
            if (c >= 0x20 && c < 0x7f && c != '\\') {
                b.append(c);
            } else {
                b.append(String.format("\\u%04x", (int) c));
            }
        }
        return b.append(s.length() > max ? "... (" + s.length() + " characters)" : "").toString();
    }

    /**
     * @param name any text, or null
     * @return {@link #printable} in single quotes ({@code no name} for null)
     */
    public static String quoted(String name) {
        return name == null ? printable(null) : "'" + printable(name) + "'";
    }

    /**
     * @param secret the run secret to present, or null
     * @return this hello presenting it
     */
    public RobotHello withToken(String secret) {
        return new RobotHello(name, robotType, parameters, secret);
    }
}
