package robosim.aria;

import java.io.PrintStream;
import java.util.Locale;

/**
 * ARIA's {@code ArLog}: a program's log lines, printf-style, on standard output, each at a level;
 * lines above the level set are left out. A port reads as the C++ does:
 * {@code ArLog.log(ArLog.Normal, "Pose: %.0f %.0f", robot.getX(), robot.getY());}. The formats are
 * Java's ({@link String#format}), which read C's {@code %d}, {@code %s}, {@code %f}, {@code %g}
 * and {@code %x} the same.
 */
public final class ArLog {
    /** How much a line matters: the fewer the level, the more it does (ARIA's {@code ArLog::LogLevel}). */
    public enum LogLevel {
        /** Errors and what a user must see. */
        Terse,
        /** What a program does, step by step (ARIA's default). */
        Normal,
        /** Detail for finding faults. */
        Verbose
    }

    /** {@link LogLevel#Terse}, as C++ names it: {@code ArLog::Terse}. */
    public static final LogLevel Terse = LogLevel.Terse;
    /** {@link LogLevel#Normal}. */
    public static final LogLevel Normal = LogLevel.Normal;
    /** {@link LogLevel#Verbose}. */
    public static final LogLevel Verbose = LogLevel.Verbose;

    private static volatile LogLevel level = LogLevel.Normal;
    private static final InheritableThreadLocal<PrintStream> OUT = new InheritableThreadLocal<>();

    private ArLog() {
    }

    /**
     * Prints a line when its level is within the level set.
     *
     * @param lineLevel the line's level
     * @param format    a {@link String#format} format
     * @param args      its values
     */
    public static void log(LogLevel lineLevel, String format, Object... args) {
        if (lineLevel.ordinal() > level.ordinal()) {
            return;
        }
        String line = args.length == 0 ? format : String.format(Locale.ROOT, format, args);
        PrintStream given = OUT.get();
        PrintStream to = given != null ? given : System.out;
        synchronized (to) {
            to.println(line);
            to.flush();
        }
    }

    /** @param lineLevel the most detailed level printed from now on (ARIA's {@code ArLog::setLogLevel}) */
    public static void setLogLevel(LogLevel lineLevel) {
        level = lineLevel;
    }

    /** @return the most detailed level printed */
    public static LogLevel getLogLevel() {
        return level;
    }

    /**
     * @param stream where the lines of the calling thread, and of the threads it starts from now on,
     *               go; null for standard output as it is when each line is printed
     */
    public static void setStream(PrintStream stream) {
        OUT.set(stream);
    }
}
