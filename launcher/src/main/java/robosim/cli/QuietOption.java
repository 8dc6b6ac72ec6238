package robosim.cli;

import picocli.CommandLine.Option;

/** {@code --quiet}, shared by the commands that show progress while they run. */
final class QuietOption {
    @Option(names = "--quiet", description = "show no progress or waiting lines while running; results and errors are still printed")
    boolean quiet;
}
