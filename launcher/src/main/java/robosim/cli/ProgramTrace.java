package robosim.cli;

import java.io.PrintWriter;
import java.util.Arrays;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.Set;

/**
 * Prints a robot program's failure as Java does, with its causes and suppressed exceptions, but
 * without the frames below the program's {@code main} that are the launcher's own: the reflection
 * that calls {@code main}, {@link RobotProgram} and the thread {@code robosim robot} runs it on (or,
 * below a static initializer that threw, the class loading and the command line). The program's own
 * frames, with their files and lines, all stay.
 */
final class ProgramTrace {
    private ProgramTrace() {
    }

    /**
     * @param failure what the program threw; its stack traces (and its causes') lose the launcher's frames
     * @param err     where to print
     */
    static void print(Throwable failure, PrintWriter err) {
        trim(failure, Collections.newSetFromMap(new IdentityHashMap<>()));
        failure.printStackTrace(err);
        err.flush();
    }

    private static void trim(Throwable t, Set<Throwable> seen) {
        if (t == null || !seen.add(t)) {
            return;
        }
        StackTraceElement[] frames = t.getStackTrace();
        // the launcher's own call into the program, and what it stands on, go; so does the reflection
        // (or the class loading) just above it. A trace without that call (a failure on a thread the
        // program started) stays whole, as does one that is nothing but the launcher's frames.
        int cut = 0;
        while (cut < frames.length && !isLaunchers(frames[cut])) {
            cut++;
        }
        while (cut > 0 && cut < frames.length && isCallGlue(frames[cut - 1])) {
            cut--;
        }
        if (cut > 0 && cut < frames.length) {
            t.setStackTrace(Arrays.copyOf(frames, cut));
        }
        trim(t.getCause(), seen);
        for (Throwable s : t.getSuppressed()) {
            trim(s, seen);
        }
    }

    /** @return whether a frame is the launcher's own: where it calls the program's {@code main} or loads its class */
    static boolean isLaunchers(StackTraceElement frame) {
        String c = frame.getClassName();
        return c.equals(RobotProgram.class.getName()) || c.startsWith(RobotProgram.class.getName() + "$")
                || c.equals(RobotCommand.class.getName());
    }

    /** @return whether a frame is the reflection, or the class loading, between the launcher and the program */
    static boolean isCallGlue(StackTraceElement frame) {
        String c = frame.getClassName();
        return c.equals("java.lang.reflect.Method") || c.startsWith("jdk.internal.reflect.")
                || c.startsWith("sun.reflect.") || c.startsWith("java.lang.invoke.") || c.equals(Class.class.getName());
    }
}
