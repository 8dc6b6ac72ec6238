package robosim.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import robosim.protocol.recording.RecordingWriter;

/** What the commands that record say about their recording. */
final class Recordings {
    private Recordings() {
    }

    /**
     * Prints where the recording went and its size, or why it stopped.
     *
     * @param out    standard output
     * @param err    standard error
     * @param cmd    the command's name, for the error line
     * @param file   the recording
     * @param writer its writer, closed
     * @return 0 if every step was recorded, 1 if writing failed
     */
    static int report(PrintWriter out, PrintWriter err, String cmd, Path file, RecordingWriter writer) {
        if (writer.failure() != null) {
            err.println("robosim " + cmd + ": recording " + file + " failed after " + writer.framesWritten()
                    + " steps: " + writer.failure().getMessage() + "; the steps before are readable");
            err.flush();
            return 1;
        }
        long steps = writer.framesWritten();
        out.printf(Locale.ROOT, "Recording: %s, %d steps in %d bytes (%.0f bytes per step%s)%n", file.toAbsolutePath(),
                steps, writer.bytesWritten(), steps == 0 ? 0.0 : (double) writer.bytesWritten() / steps,
                writer.sensors() ? ", sensors kept" : "");
        out.flush();
        return 0;
    }
}
