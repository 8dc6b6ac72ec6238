package robosim.cli;

import java.io.PrintWriter;
import java.util.logging.Filter;
import java.util.logging.Handler;
import java.util.logging.Logger;

/**
 * Where a command shows its progress, on standard error. On a terminal it is one line, redrawn in
 * place with a carriage return and cleared before a log line or the command's results; anywhere
 * else every {@link #show} is a plain line of its own, for a log file (the caller shows few).
 */
final class StatusLine implements AutoCloseable {
    private final PrintWriter err;
    private final boolean terminal;
    private final int width;
    private final Handler[] hooked;
    private final Filter[] filters;
    private final Thread onExit;
    private int shown;

    /**
     * @param err      where to print
     * @param terminal whether {@code err} is a terminal: one line redrawn in place, and log records
     *                 (on the root logger's handlers) clear it before they are written
     * @param width    the terminal's width; a longer line is cut to fit, so that it never wraps
     */
    StatusLine(PrintWriter err, boolean terminal, int width) {
        this.err = err;
        this.terminal = terminal;
        this.width = Math.max(20, width);
        this.hooked = terminal ? Logger.getLogger("").getHandlers() : new Handler[0];
        this.filters = new Filter[hooked.length];
        for (int i = 0; i < hooked.length; i++) {
            Filter before = hooked[i].getFilter();
            filters[i] = before;
            hooked[i].setFilter(record -> {
                if (before != null && !before.isLoggable(record)) {
                    return false;
                }
                clear();
                return true;
            });
        }
        // stopped by Ctrl-C or kill: the last status stays, and the shell's prompt starts a line of its own
        onExit = terminal ? new Thread(this::endLine, "status-line-end") : null;
        if (onExit != null) {
            Runtime.getRuntime().addShutdownHook(onExit);
        }
    }

    private synchronized void endLine() {
        if (shown > 0) {
            err.println();
            err.flush();
            shown = 0;
        }
    }

    /** @return a status line on standard error as the launcher's {@code err} writer has it */
    static StatusLine on(PrintWriter err) {
        boolean terminal = Terminal.stderrIsTerminal();
        return new StatusLine(err, terminal, terminal ? Terminal.width() : Terminal.DEFAULT_WIDTH);
    }

    /** @return whether the line is redrawn in place */
    boolean isTerminal() {
        return terminal;
    }

    /**
     * Shows a status: on a terminal in place of the one shown, elsewhere as a line of its own.
     *
     * @param text one line
     */
    synchronized void show(String text) {
        if (!terminal) {
            err.println(text);
            err.flush();
            return;
        }
        String fitted = text.length() > width - 1 ? text.substring(0, width - 2) + "~" : text;
        StringBuilder b = new StringBuilder(width + 2).append('\r').append(fitted);
        for (int i = fitted.length(); i < shown; i++) {
            b.append(' ');
        }
        if (fitted.length() < shown) {
            b.append('\r').append(fitted);
        }
        err.print(b);
        err.flush();
        shown = fitted.length();
    }

    /** Clears the line shown on a terminal, so that what follows starts on a clean line. */
    synchronized void clear() {
        if (!terminal || shown == 0) {
            return;
        }
        err.print("\r" + " ".repeat(shown) + "\r");
        err.flush();
        shown = 0;
    }

    /** Clears the line and stops clearing it for log records. */
    @Override
    public void close() {
        clear();
        for (int i = 0; i < hooked.length; i++) {
            hooked[i].setFilter(filters[i]);
        }
        if (onExit != null) {
            try {
                Runtime.getRuntime().removeShutdownHook(onExit);
            } catch (IllegalStateException e) {
                // the JVM is already shutting down: the hook runs, and finds the line cleared
            }
        }
    }
}
