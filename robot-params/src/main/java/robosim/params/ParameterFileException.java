package robosim.params;

import java.nio.file.Path;

/** A robot parameter file broke a rule; the message names the file, the line and the rule. */
public final class ParameterFileException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /**
     * @param file the file read
     * @param line the 1-based line, or 0 when the problem concerns the whole file
     * @param rule what was wrong
     */
    public ParameterFileException(Path file, int line, String rule) {
        super(message(file, line, rule));
    }

    /**
     * @param file  the file read
     * @param line  the 1-based line, or 0 when the problem concerns the whole file
     * @param rule  what was wrong
     * @param cause the parser's own error, kept for the stack trace
     */
    public ParameterFileException(Path file, int line, String rule, Throwable cause) {
        super(message(file, line, rule), cause);
    }

    private static String message(Path file, int line, String rule) {
        return line > 0 ? file + ":" + line + ": " + rule : file + ": " + rule;
    }
}
