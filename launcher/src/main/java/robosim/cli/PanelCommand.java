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
                + " running one with --port), control the run (pause, resume, step, stop, restart, pace), watch it live,"
                + " add robot programs, move and remove robots, read the Environment's log.",
            "Closing the window stops every JVM it started."})
final class PanelCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "WORLD",
            description = "the world to select (and, without --port, to offer first); default: the shipped worlds")
    Path world;

    @Option(names = "--host", defaultValue = "127.0.0.1", paramLabel = "HOST",
            description = "with --port: the running Environment's host; default ${DEFAULT-VALUE}")
    String host;

    @Option(names = "--port", paramLabel = "PORT", description = "attach at once to the Environment whose viewer port"
            + " this is, instead of starting one")
    Integer port;

    @Option(names = "--robot-port", defaultValue = "0", paramLabel = "PORT",
            description = "with --port: its robot port, so that robots can be added; default: not known")
    int robotPort;

    @Option(names = "--secret-file", paramLabel = "FILE", description = "with --port: the file holding the run"
            + " secret; default: as every client finds it ($" + RunSecret.ENV + ", $" + RunSecret.FILE_ENV
            + ", ~/.robosim/tokens/PORT)")
    Path secretFile;

    @Option(names = "--start", description = "start the Environment on WORLD at once, with the default settings")
    boolean start;

    @Override
    public Integer call() throws Exception {
        if (port != null && (port < 1 || port > 65535)) {
            throw new ParameterException(spec.commandLine(), "--port: a port from 1 to 65535, got " + port);
        }
        if (world != null && !Files.isRegularFile(world)) {
            throw new ParameterException(spec.commandLine(), "WORLD: no such file: " + world);
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
                if (port != null) {
                    w[0].attach(host, port, robotPort, token);
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
