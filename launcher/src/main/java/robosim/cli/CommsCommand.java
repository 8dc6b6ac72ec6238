package robosim.cli;

import java.io.IOException;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import robosim.panel.net.ControlClient;
import robosim.protocol.CommsUpdate;

/** {@code robosim comms}: changes a running Environment's communication settings. */
@Command(name = "comms", mixinStandardHelpOptions = true,
        description = "Change how messages travel in a running Environment; settings not given stay as they are.")
final class CommsCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Mixin
    ViewerPortOptions at;

    @Mixin
    SecretOption secret;

    @Option(names = "--range", paramLabel = "MM", description = "the farthest a message reaches (0: no limit)")
    Double range;

    @Option(names = "--walls-block", arity = "1", paramLabel = "true|false", description = "whether walls stop messages")
    Boolean wallsBlock;

    @Option(names = "--latency", paramLabel = "STEPS", description = "steps from sending to delivery, at least 1")
    Integer latency;

    @Option(names = "--loss", paramLabel = "P", description = "the chance a message is lost, 0 to 1")
    Double loss;

    @Option(names = "--max-bytes", paramLabel = "N", description = "the largest message, bytes")
    Integer maxBytes;

    @Override
    public Integer call() {
        if (range == null && wallsBlock == null && latency == null && loss == null && maxBytes == null) {
            throw new ParameterException(spec.commandLine(), "give at least one setting to change: --range, --walls-block, --latency, --loss or --max-bytes");
        }
        String token = ControlConnection.token(spec, secret, at);
        try {
            CommsUpdate now = ControlConnection.exchange(at, "comms", token, 10_000, c -> {
                c.send(new CommsUpdate(range, wallsBlock, latency, loss, maxBytes));
                return c.answer(CommsUpdate.class, u -> true);
            });
            spec.commandLine().getOut().printf(java.util.Locale.ROOT,
                    "Comms settings now: range %.0f mm, walls block %s, latency %d, loss %.3f, max %d bytes%n",
                    now.maxRange(), now.wallsBlock(), now.latencySteps(), now.lossProbability(), now.maxMessageBytes());
            return 0;
        } catch (ControlClient.NoAnswerException e) {
            spec.commandLine().getErr().println("robosim comms: " + e.getMessage());
            return 1;
        } catch (IOException e) {
            spec.commandLine().getErr().println("robosim comms: cannot reach the Environment at " + at.host + ":" + at.port()
                    + ": " + e.getMessage());
            return 1;
        }
    }
}
