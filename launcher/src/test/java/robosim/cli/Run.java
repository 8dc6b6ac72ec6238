package robosim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;
import picocli.CommandLine;

/**
 * A command line run in the test's JVM, as {@code bin/robosim} would run it, with what it printed.
 *
 * @param exit the exit code
 * @param out  what it printed on standard output
 * @param err  what it printed on standard error
 */
record Run(int exit, String out, String err) {
    /** Runs {@code robosim ARGS...} and keeps what it printed. */
    static Run execute(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        int exit = cl.execute(args);
        return new Run(exit, out.toString(), err.toString());
    }

    /** @return standard error's lines, without the blank ones around them */
    List<String> errLines() {
        return err.strip().lines().toList();
    }

    /** Fails if standard error holds a stack trace. */
    void assertNoStackTrace() {
        assertFalse(err.contains("\tat ") || err.contains("Exception"), "a one-line error, not a stack trace:\n" + err);
    }

    /** @return standard error's first line */
    String firstLine() {
        return err.lines().findFirst().orElse("");
    }

    /** Checks that a bad value is one line, then the pointer to --help. */
    void assertHintToHelp(String command) {
        assertEquals(List.of(firstLine(), "Try '" + command + " --help'."), errLines(), err);
    }
}
