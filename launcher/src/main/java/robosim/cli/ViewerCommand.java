package robosim.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code robosim viewer}: attaches to a running Environment and writes PNG frames. */
@Command(name = "viewer", mixinStandardHelpOptions = true,
        description = "Attach to a running Environment and write its frames as PNG files.")
final class ViewerCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--host", defaultValue = "localhost", description = "the Environment's host; default ${DEFAULT-VALUE}")
    String host;

    @Option(names = "--port", defaultValue = "3000", description = "the Environment's viewer port; default ${DEFAULT-VALUE}")
    int port;

    @Option(names = "--png-dir", required = true, paramLabel = "DIR", description = "where to write frame-NNNNNN.png")
    Path pngDir;

    @Option(names = "--every", defaultValue = "1", paramLabel = "K", description = "write every K-th step; default ${DEFAULT-VALUE}")
    int every;

    @Option(names = "--width", defaultValue = "800", paramLabel = "PX", description = "frame width in pixels; default ${DEFAULT-VALUE}")
    int width;

    @Option(names = "--sonar", description = "draw the sonar rays")
    boolean sonar;

    @Option(names = "--no-names", description = "do not label the robots")
    boolean noNames;

    @Override
    public Integer call() {
        return Viewers.run(spec, host, port, pngDir, every, width, sonar, !noNames);
    }
}
