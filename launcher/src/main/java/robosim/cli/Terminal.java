package robosim.cli;

import java.io.Console;
import java.io.File;
import java.io.IOException;
import java.lang.reflect.Method;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

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
            boolean tty = target.startsWith("/dev/pts/") || target.startsWith("/dev/tty") || target.equals("/dev/console");
            return tty && !inBackground();
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            return consoleIsTerminal();
        }
    }

    /**
     * Whether this process runs as a background job of its terminal ({@code robosim env ... &}):
     * its process group is not the terminal's foreground group, so a line redrawn in place would
     * land in the middle of what the foreground program prints.
     */
    private static boolean inBackground() {
        try {
            String stat = Files.readString(Path.of("/proc/self/stat"));
            // after the command name, in parentheses: state, ppid, pgrp, session, tty_nr, tpgid
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
            return !f[2].equals(f[5]);
        } catch (IOException | RuntimeException e) {
            return false;
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

    /**
     * @return the terminal's width: {@code COLUMNS} if the shell exports it, else what {@code stty size}
     *         says of the terminal (shells seldom export {@code COLUMNS}), else {@value #DEFAULT_WIDTH}
     */
    static int width() {
        Integer columns = parseWidth(System.getenv("COLUMNS"));
        if (columns != null) {
            return columns;
        }
        File tty = new File("/dev/tty");
        if (tty.exists()) {
            try {
                Process stty = new ProcessBuilder("stty", "size").redirectInput(tty)
                        .redirectError(ProcessBuilder.Redirect.DISCARD).start();
                String size = new String(stty.getInputStream().readAllBytes(), StandardCharsets.US_ASCII).trim();
                if (stty.waitFor(2, TimeUnit.SECONDS) && stty.exitValue() == 0) {
                    String[] rowsColumns = size.split("\\s+");
                    Integer w = rowsColumns.length == 2 ? parseWidth(rowsColumns[1]) : null;
                    if (w != null) {
                        return w;
                    }
                }
            } catch (IOException e) {
                // no stty: the default below
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        return DEFAULT_WIDTH;
    }

    private static Integer parseWidth(String text) {
        if (text == null) {
            return null;
        }
        try {
            int w = Integer.parseInt(text.trim());
            return w >= 20 && w <= 1000 ? w : null;
        } catch (NumberFormatException e) {
            return null;
        }
    }
}
