package robosim.cli;

import picocli.CommandLine.Option;

/** Where a running Environment's viewer port is: shared by the commands that attach to it. */
final class ViewerPortOptions {
    @Option(names = "--host", defaultValue = "localhost", description = "the Environment's host; default ${DEFAULT-VALUE}")
    String host;

    @Option(names = "--port", defaultValue = "3000", description = "the Environment's viewer port; default ${DEFAULT-VALUE}")
    int port;
}
