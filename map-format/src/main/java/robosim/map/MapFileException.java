package robosim.map;

import java.nio.file.Path;

/**
 * A map file broke a rule. The message reads {@code FILE:LINE: rule}, or {@code FILE: rule} when
 * the problem concerns the whole file.
 */
public final class MapFileException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /** The map file; transient because {@link Path} is not serializable. */
    private final transient Path file;
    private final int line;
    private final String rule;

    /**
     * @param file the map file
     * @param line the 1-based line, or 0 for the whole file
     * @param rule what was wrong
     */
    public MapFileException(Path file, int line, String rule) {
        super(line > 0 ? file + ":" + line + ": " + rule : file + ": " + rule);
        this.file = file;
        this.line = line;
        this.rule = rule;
    }

    /** @return the map file */
    public Path file() {
        return file;
    }

    /** @return the 1-based line, or 0 for the whole file */
    public int line() {
        return line;
    }

    /** @return the rule that was broken, without the file and line */
    public String rule() {
        return rule;
    }
}
