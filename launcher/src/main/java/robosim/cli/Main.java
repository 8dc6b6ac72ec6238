package robosim.cli;

import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The {@code bin/robosim} launcher: one picocli subcommand per component. */
@Command(name = "robosim", mixinStandardHelpOptions = true, version = "RoboSim 0.1.0",
        description = "RoboSim, a multi-robot simulator: an Environment server, robot clients and viewers.",
        subcommands = {EnvCommand.class, RobotCommand.class, ViewerCommand.class, ReplayCommand.class, DemoCommand.class,
                BenchCommand.class, MazeCommand.class, GoldfinderCommand.class, CommsCommand.class, ControlCommand.class,
                RemoteCommand.class, PanelCommand.class, ClasspathCommand.class, ExperimentCommand.class, CommandLine.HelpCommand.class})
public final class Main implements Callable<Integer> {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    /**
     * Runs the launcher.
     *
     * @param args the command line
     */
    public static void main(String[] args) {
        Logging.configure();
        System.exit(commandLine().execute(args));
    }

    /**
     * @return the launcher's command line, for tests to execute with captured writers; a bad command
     *         line gets a one-line error and a pointer to {@code --help} (see {@link ShortErrors})
     */
    public static CommandLine commandLine() {
        return new CommandLine(new Main()).setParameterExceptionHandler(new ShortErrors());
    }

    @Override
    public Integer call() {
        spec.commandLine().usage(spec.commandLine().getErr());
        return 2;
    }
}
