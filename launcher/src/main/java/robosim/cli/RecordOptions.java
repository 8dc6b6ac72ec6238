package robosim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import picocli.CommandLine.Option;
import robosim.protocol.recording.RecordingWriter;

/** {@code --record} and {@code --record-sensors}, shared by the commands that record a run. */
final class RecordOptions {
    @Option(names = "--record", paramLabel = "FILE", description = "record every step to FILE (see robosim replay)")
    Path file;

    @Option(names = "--record-sensors", description = "keep the sonar and laser readings in the recording")
    boolean sensors;

    /** @return whether a recording was asked for */
    boolean requested() {
        return file != null;
    }

    /**
     * Creates the recording asked for.
     *
     * @param err where a failure is told
     * @param cmd the command's name, for the error line
     * @return the writer, or null if the file cannot be created (the reason is printed)
     */
    RecordingWriter create(PrintWriter err, String cmd) {
        try {
            return RecordingWriter.create(file, sensors);
        } catch (IOException e) {
            err.println("robosim " + cmd + ": cannot create recording " + file + ": " + e.getMessage());
            return null;
        }
    }

    /**
     * Prints where the recording went and its size, or why it stopped.
     *
     * @param out    standard output
     * @param err    standard error
     * @param cmd    the command's name, for the error line
     * @param writer the recording's writer, closed
     * @return 0 if every step was recorded, 1 if writing failed
     */
    int report(PrintWriter out, PrintWriter err, String cmd, RecordingWriter writer) {
        if (writer.failure() != null) {
            err.println("robosim " + cmd + ": recording " + file + " failed after " + writer.snapshotsWritten()
                    + " steps: " + writer.failure().getMessage() + "; the steps before are readable");
            err.flush();
            return 1;
        }
        long steps = writer.snapshotsWritten();
        out.printf(Locale.ROOT, "Recording: %s, %d steps in %d bytes (%.0f bytes per step%s)%n", file.toAbsolutePath(),
                steps, writer.bytesWritten(), steps == 0 ? 0.0 : (double) writer.bytesWritten() / steps,
                writer.sensors() ? ", sensors kept" : "");
        out.flush();
        return 0;
    }
}
