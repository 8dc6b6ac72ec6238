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
 * images written as PNG (and, if asked, a recording and an animated GIF), the summary printed.
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = "Run the demo: GoldFinder with 3 robots, each in its own JVM, on the medium maze; frames written as PNG, showing what the robots draw.")
final class DemoCommand implements Callable<Integer> {
    /** The wander robot, for runs that need robots that just keep moving. */
    static final String WANDER = "robosim.examples.wander.Wander";

    @Spec
    CommandSpec spec;

    @Option(names = "--out-dir", defaultValue = "out/demo", paramLabel = "DIR", description = OptionTexts.OUT_DIR
            + "; frames in DIR/frames, each robot's log in DIR/rN.log; default ${DEFAULT-VALUE}")
    Path out;

    @Option(names = "--out", hidden = true, paramLabel = "DIR", description = OptionTexts.OLD_NAME + "--out-dir")
    Path oldOut;

    @Option(names = "--steps", defaultValue = "20000", paramLabel = "N", description = OptionTexts.STEPS
            + "; the search stops there if the gold is not found; default ${DEFAULT-VALUE}")
    long maxSteps;

    @Option(names = "--max-steps", hidden = true, paramLabel = "N", description = OptionTexts.OLD_NAME + "--steps")
    Long oldMaxSteps;

    @Option(names = "--every", defaultValue = OptionTexts.EVERY_DEFAULT, paramLabel = "K", description = OptionTexts.EVERY)
    int every;

    @Mixin
    RecordOptions recording = new RecordOptions();

    @Option(names = "--gif", paramLabel = "FILE",
            description = "write an animated GIF that loops; of the frames, played at " + GoldfinderCommand.GIF_SPEED + "x simulated time")
    Path gif;

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
        gold.out = oldOut != null ? oldOut : out;
        gold.maxSteps = oldMaxSteps != null ? oldMaxSteps : maxSteps;
        gold.every = every;
        gold.recording = recording;
        gold.gif = gif;
        // the frames show each robot's known map and claimed frontier: the division of work
        gold.drawings = true;
        return gold.call();
    }
}
