package robosim.cli;

import picocli.CommandLine.Option;

/** Where a running Environment's viewer port is: shared by the commands that attach to it. */
final class ViewerPortOptions {
    @Option(names = "--host", defaultValue = "localhost", paramLabel = "HOST",
            description = "the Environment's host; default ${DEFAULT-VALUE}")
    String host;

    @Option(names = "--viewer-port", defaultValue = "3000", paramLabel = "PORT", description = OptionTexts.VIEWER_PORT
            + "; the Environment's, where viewers connect; default ${DEFAULT-VALUE}")
    int viewerPort;

    @Option(names = "--port", hidden = true, paramLabel = "PORT", description = OptionTexts.OLD_NAME + "--viewer-port")
    Integer oldPort;

    /** @return the viewer port given, under its name or its old name {@code --port} */
    int port() {
        return oldPort != null ? oldPort : viewerPort;
    }
}
