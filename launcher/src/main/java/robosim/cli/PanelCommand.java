package robosim.cli;

import java.awt.AWTError;
import java.awt.HeadlessException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import javax.swing.SwingUtilities;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import robosim.panel.model.RunSettings;
import robosim.panel.window.ControlPanelWindow;
import robosim.panel.window.RunForm;
import robosim.params.RobotParameterFiles;
import robosim.protocol.RunSecret;

/**
 * {@code robosim panel}: the ControlPanel window, to start an Environment in a JVM of its own (or
 * attach to a running one), control the run, and watch, add, move and remove its robots.
 */
@Command(name = "panel", mixinStandardHelpOptions = true,
        description = {"Open the ControlPanel: start an Environment on WORLD in a JVM of its own (or attach to a"
                + " running one with --attach), control the run (pause, resume, step, stop, restart, pace), watch it live,"
                + " add robot programs, move and remove robots, read the Environment's log.",
            "Closing the window stops every JVM it started."})
final class PanelCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "WORLD",
            description = "the world to select in the new-run form (with --start: to start); default: the first shipped world")
    Path world;

    @Option(names = "--attach", description = "attach at once to the running Environment at --host and --viewer-port"
            + " instead of starting one")
    boolean attach;

    @Option(names = "--host", defaultValue = "localhost", paramLabel = "HOST",
            description = "the Environment's host; with --attach; default ${DEFAULT-VALUE}")
    String host;

    @Option(names = "--viewer-port", defaultValue = "3000", paramLabel = "PORT", description = OptionTexts.VIEWER_PORT
            + "; with --attach: the running Environment's, where the panel attaches; default ${DEFAULT-VALUE}")
    int viewerPort;

    @Option(names = "--robot-port", defaultValue = "5000", paramLabel = "PORT", description = OptionTexts.ROBOT_PORT
            + "; with --attach: the running Environment's, where the robots the panel adds connect; default"
            + " ${DEFAULT-VALUE}")
    int robotPort;

    @Option(names = "--secret-file", paramLabel = "FILE", description = OptionTexts.SECRET_FILE
            + "; with --attach; default: as every client finds it ($" + RunSecret.ENV + ", $" + RunSecret.FILE_ENV
            + ", ~/.robosim/tokens/PORT)")
    Path secretFile;

    @Option(names = "--start", description = "start the Environment on WORLD at once, with the default settings")
    boolean start;

    @Override
    public Integer call() throws Exception {
        requirePort("--viewer-port", viewerPort);
        requirePort("--robot-port", robotPort);
        if (world != null && !Files.isRegularFile(world)) {
            throw new ParameterException(spec.commandLine(), "WORLD: no such file: " + world);
        }
        if (start && attach) {
            throw new ParameterException(spec.commandLine(), "--start and --attach: give one, a panel runs one Environment");
        }
        if (start && world == null) {
            throw new ParameterException(spec.commandLine(), "--start: give the WORLD to start");
        }
        String token = token();
        if (!Windows.prepare(spec.commandLine().getErr(), "robosim panel")) {
            return 1;
        }
        ControlPanelWindow[] w = new ControlPanelWindow[1];
        try {
            SwingUtilities.invokeAndWait(() -> {
                w[0] = new ControlPanelWindow(RunForm.worldsIn(RobotParameterFiles.root()
                        .resolve("testLoadFiles/environment")), world == null ? null : world.toAbsolutePath());
                w[0].setVisible(true);
                if (attach) {
                    w[0].attach(host, viewerPort, robotPort, token);
                } else if (start) {
                    w[0].start(RunSettings.parse(world.toString(), "1", "0", "0", "127.0.0.1"));
                }
            });
        } catch (HeadlessException | AWTError e) {
            spec.commandLine().getErr().println("robosim panel: cannot open a window: " + e.getMessage());
            return 1;
        }
        w[0].awaitClosed();
        return 0;
    }

    private void requirePort(String option, int value) {
        if (value < 1 || value > 65535) {
            throw new ParameterException(spec.commandLine(), option + ": a port from 1 to 65535, got " + value);
        }
    }

    private String token() {
        if (secretFile == null) {
            return null;
        }
        try {
            return RunSecret.check(Files.readString(secretFile).strip());
        } catch (IOException | IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), "--secret-file: " + secretFile + ": " + e.getMessage());
        }
    }
}
