package robosim.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import robosim.params.RobotParameterFiles;

/**
 * {@code robosim demo}: GoldFinder with 3 Pioneers, each in a JVM of its own, on the medium maze;
 * images written as PNG, the summary printed.
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = "Run the demo: GoldFinder with 3 robots, each in its own JVM, on the medium maze; frames written as PNG.")
final class DemoCommand implements Callable<Integer> {
    /** The wander robot, for runs that need robots that just keep moving. */
    static final String WANDER = "robosim.examples.wander.Wander";

    @Spec
    CommandSpec spec;

    @Option(names = "--out", defaultValue = "out/demo", paramLabel = "DIR", description = "where the frames go; default ${DEFAULT-VALUE}")
    Path out;

    @Option(names = "--max-steps", defaultValue = "20000", paramLabel = "N", description = "step limit; default ${DEFAULT-VALUE}")
    long maxSteps;

    @Option(names = "--every", defaultValue = "20", paramLabel = "K", description = "write a frame every K steps; default ${DEFAULT-VALUE}")
    int every;

    @Mixin
    QuietOption quiet;

    @Override
    public Integer call() throws Exception {
        GoldfinderCommand gold = new GoldfinderCommand();
        gold.quiet = quiet;
        gold.spec = spec;
        gold.world = RobotParameterFiles.root().resolve("testLoadFiles/environment/maze-medium.xml");
        gold.robots = 3;
        gold.separateJvms = true;
        gold.seed = 1;
        gold.out = out;
        gold.maxSteps = maxSteps;
        gold.every = every;
        gold.cellSize = 1500;
        return gold.call();
    }
}
