package robosim.cli;

import java.io.Console;
import java.io.IOException;
import java.lang.reflect.Method;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Whether standard error is a terminal, so that progress may be one line that updates in place
 * (carriage returns) rather than plain lines for a log file.
 */
final class Terminal {
    /** Terminal width when {@code COLUMNS} does not say. */
    static final int DEFAULT_WIDTH = 80;

    private Terminal() {
    }

    /**
     * On Linux, where file descriptor 2 points says it exactly. Elsewhere {@link System#console()}
     * tells whether the JVM runs in a terminal: on JDK 17 it is null when standard input or output is
     * redirected; from JDK 22 it is never null, and {@code Console.isTerminal()} (looked up by
     * reflection, since JDK 17 has none) tells. A {@code TERM} of {@code dumb} is no terminal.
     *
     * @return whether standard error is a terminal that understands a carriage return
     */
    static boolean stderrIsTerminal() {
        if ("dumb".equals(System.getenv("TERM"))) {
            return false;
        }
        Path fd2 = Path.of("/proc/self/fd/2");
        try {
            String target = Files.readSymbolicLink(fd2).toString();
            return target.startsWith("/dev/pts/") || target.startsWith("/dev/tty") || target.equals("/dev/console");
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            return consoleIsTerminal();
        }
    }

    private static boolean consoleIsTerminal() {
        Console console = System.console();
        if (console == null) {
            return false;
        }
        try {
            Method isTerminal = Console.class.getMethod("isTerminal");
            return Boolean.TRUE.equals(isTerminal.invoke(console));
        } catch (NoSuchMethodException e) {
            return true; // JDK 17 to 21: a console is there only in a terminal
        } catch (ReflectiveOperationException | RuntimeException e) {
            return false;
        }
    }

    /** @return the terminal's width from {@code COLUMNS}, or {@value #DEFAULT_WIDTH} */
    static int width() {
        String columns = System.getenv("COLUMNS");
        if (columns != null) {
            try {
                int w = Integer.parseInt(columns.trim());
                if (w >= 20 && w <= 1000) {
                    return w;
                }
            } catch (NumberFormatException e) {
                // the default below
            }
        }
        return DEFAULT_WIDTH;
    }
}
