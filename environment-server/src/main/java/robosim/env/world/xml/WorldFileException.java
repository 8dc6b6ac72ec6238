package robosim.env.world.xml;

import java.nio.file.Path;

/**
 * A world file broke a rule. The message reads {@code FILE:LINE: rule}, or {@code FILE: rule}
 * when the problem concerns the whole file (it cannot be read, say).
 */
public final class WorldFileException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /** The world file; transient because {@link Path} is not serializable. */
    private final transient Path file;
    /** The 1-based line of the offending element, or 0. */
    private final int line;
    /** The rule that was broken. */
    private final String rule;

    /**
     * @param file the world file
     * @param line the 1-based line of the offending element, or 0 for the whole file
     * @param rule what was wrong
     */
    public WorldFileException(Path file, int line, String rule) {
        this(file, line, rule, null);
    }

    /**
     * @param file  the world file
     * @param line  the 1-based line of the offending element, or 0 for the whole file
     * @param rule  what was wrong
     * @param cause the underlying error, or {@code null}
     */
    public WorldFileException(Path file, int line, String rule, Throwable cause) {
        super(line > 0 ? file + ":" + line + ": " + rule : file + ": " + rule, cause);
        this.file = file;
        this.line = line;
        this.rule = rule;
    }

    /** @return the world file */
    public Path file() {
        return file;
    }

    /** @return the 1-based line of the offending element, or 0 for the whole file */
    public int line() {
        return line;
    }

    /** @return the rule that was broken, without the file and line */
    public String rule() {
        return rule;
    }
}
