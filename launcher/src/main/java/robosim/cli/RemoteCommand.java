package robosim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.function.Supplier;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import robosim.hw.RunEnd;
import robosim.params.RobotParameterFiles;
import robosim.protocol.RobotKind;
import robosim.protocol.RobotParameters;
import robosim.protocol.RunSecret;
import robosim.remote.robot.PioneerRemote;
import robosim.remote.robot.RemoteRobot;
import robosim.remote.robot.ScoutRemote;
import robosim.remote.window.RemoteSession;
import robosim.scout.Scout;
import robosim.viewer.net.ViewerOptions;

/**
 * {@code robosim remote}: the RemoteControl, a robot program driven by hand from a window: a Pioneer
 * (ArRobot) or a Scout connects as the world's robot NAME, and the window drives it, shows its
 * readings and parameters, sends its messages and shows the world following it.
 */
@Command(name = "remote", mixinStandardHelpOptions = true,
        description = {"Drive a robot by hand from a window: the robot NAME of the world the Environment at HOST:PORT"
                + " (its robot port) runs, as a Pioneer (ArRobot) or, with --scout, a Scout.",
            "Buttons (forward, back, left, right, stop) latch; the arrow keys drive while held and the space bar stops."
                    + " Sliders set the speeds within the robot's limits; the move and heading fields send move and"
                    + " setHeading; sonar, laser and heat switch on and off. The window shows the robot's parameters,"
                    + " its readings (a polar plot of the sonar ring and laser scan, pose, velocities, stall, messages"
                    + " received), a box to send messages, and the world from the viewer port, following the robot.",
            "HOST may be any address the Environment listens on, from another machine too."},
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = {"0:the window was closed, or the run ended",
                "1:the robot could not connect, or no window could be opened",
                "2:bad command line"})
final class RemoteCommand implements Callable<Integer> {
    /** The longest wait for the robot's welcome, ms. */
    private static final long CONNECT_TIMEOUT_MS = 120_000;

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "NAME", description = "the robot's name in the world")
    String name;

    @Parameters(index = "1", paramLabel = "HOST", description = "the Environment's host")
    String host;

    @Parameters(index = "2", paramLabel = "PORT", description = "the Environment's robot port")
    int port;

    @Option(names = "--scout", description = "drive a Scout (the Nomadic API) instead of a Pioneer; the same as --type scout")
    boolean scout;

    @Option(names = "--type", paramLabel = "TYPE",
            description = "the robot's API: pioneer (ArRobot) or scout; default pioneer")
    String type;

    @Option(names = "--params", paramLabel = "FILE",
            description = "the robot's parameter file: a path, or a shipped name such as p3dx or scout; default p3dx"
                    + " for a Pioneer, scout for a Scout")
    String params;

    @Option(names = "--viewer-port", defaultValue = "3000", paramLabel = "PORT", description = OptionTexts.VIEWER_PORT
            + "; the Environment's, on HOST, for the view following the robot; default ${DEFAULT-VALUE}")
    int viewerPort;

    @Option(names = "--keydrive", description = "the arrow keys feed ARIA's ArActionKeydrive (each press: 25 mm/s"
            + " faster or slower up to 400, or a turn of 8 degrees), as ARIA's key handler does, instead of driving"
            + " while held; a Pioneer only")
    boolean keydrive;

    @Option(names = "--no-view", description = "show no view of the world (the viewer port is not reached)")
    boolean noView;

    @Option(names = "--secret-file", paramLabel = "FILE",
            description = OptionTexts.SECRET_FILE + "; default: as every robot finds it (--token,"
                    + " $ROBOSIM_TOKEN, $ROBOSIM_TOKEN_FILE, ~/.robosim/tokens/PORT)")
    Path secretFile;

    @Mixin
    SecretOption secret;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        RobotKind kind = scout ? RobotKind.SCOUT : type == null ? RobotKind.PIONEER : RobotKind.of(type).orElseThrow(() -> bad("'" + type
                + "' was supplied for --type: it is " + String.join(" or ", RobotKind.ids())));
        boolean isScout = kind == RobotKind.SCOUT;
        if (isScout && keydrive) {
            throw bad("--keydrive was given for a Scout: the keydrive action is ARIA's, a Pioneer's");
        }
        requirePort("PORT", port);
        requirePort("--viewer-port", viewerPort);
        String file = params != null ? params : kind.defaultParameters();
        RobotParameters parameters;
        try {
            parameters = RobotParameterFiles.load(file);
        } catch (RuntimeException e) {
            throw bad("--params: " + e.getMessage());
        }
        applySecret();
        if (!Windows.prepare(err, "robosim remote")) {
            return 1;
        }
        Supplier<RemoteRobot> connect = isScout ? () -> ScoutRemote.connect(name, host, port, parameters)
                : () -> PioneerRemote.connect(name, host, port, parameters, keydrive);
        ViewerOptions view = noView ? null : ViewerOptions.of(host, viewerPort);
        RemoteSession session;
        try {
            session = RemoteSession.open(connect, file, view, CONNECT_TIMEOUT_MS);
        } catch (IllegalStateException e) {
            err.println("robosim remote: " + e.getMessage());
            return 1;
        }
        try {
            session.awaitEnd();
        } finally {
            RunEnd end = session.robot().runEnd();
            session.close();
            out.println(end != null ? end.describe() : "robot " + name + " left the run: the window was closed");
            out.flush();
        }
        return 0;
    }

    private void applySecret() {
        String wrong = secret.apply();
        if (wrong != null) {
            throw bad(wrong);
        }
        if (secretFile == null) {
            return;
        }
        if (secret.token != null) {
            throw bad("--secret-file was given with --token: give the secret one way");
        }
        try {
            String s = Files.readString(secretFile, StandardCharsets.UTF_8).strip();
            System.setProperty(RunSecret.PROPERTY, RunSecret.check(s));
        } catch (IOException e) {
            throw bad("'" + secretFile + "' was supplied for --secret-file: it cannot be read (" + e.getMessage() + ")");
        } catch (IllegalArgumentException e) {
            throw bad("'" + secretFile + "' was supplied for --secret-file: " + e.getMessage());
        }
    }

    private void requirePort(String option, int value) {
        if (value < 1 || value > 65535) {
            throw bad(value + " was supplied for " + option + ": a port is 1 to 65535");
        }
    }

    private ParameterException bad(String message) {
        return new ParameterException(spec.commandLine(), message);
    }
}
