package robosim.experiment;

import java.nio.file.Path;

/**
 * An experiment file breaks a rule: the message names the file, the line and the rule, as the world
 * reader's errors do ({@code teams.yaml line 12: ...}).
 */
public final class ExperimentFileException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    private final transient Path file;
    private final int line;

    /**
     * @param file    the experiment file
     * @param line    the line, from 1; 0 if the error is of the whole file
     * @param message what is wrong and the rule, without the file and line
     */
    public ExperimentFileException(Path file, int line, String message) {
        super(file + (line > 0 ? " line " + line : "") + ": " + message);
        this.file = file;
        this.line = line;
    }

    /** @return the experiment file */
    public Path file() {
        return file;
    }

    /** @return the line, from 1, or 0 if the error is of the whole file */
    public int line() {
        return line;
    }
}
