package robosim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.net.SocketTimeoutException;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import robosim.panel.net.ControlClient;
import robosim.panel.model.RobotRows;
import robosim.protocol.ControlReply;
import robosim.protocol.ControlRequest;
import robosim.protocol.RunStatus;

/**
 * {@code robosim control}: pauses, resumes, steps, paces or stops a running Environment, moves or
 * removes one of its robots, or restarts its run or loads another world, for scripts: the
 * Environment's answer is printed, and a refusal exits 1.
 */
@Command(name = "control", mixinStandardHelpOptions = true,
        description = {"Control a running Environment and print its answer; exit 1 when it refuses.",
            "Operations: pause | resume | step N (while paused: run N steps, then pause) | stop (end the run"
                    + " cleanly) | pace max|realtime|K (K times real time) | move NAME X Y TH (mm, mm, degrees;"
                    + " odometry unchanged) | remove NAME | restart (the same world and seed from step 0) | load WORLD"
                    + " (another world file, read by the Environment, under the directory of the world it was"
                    + " started with) | status (the run and a tab-separated table of its robots).",
            "The Environment carries each out between two steps. On restart and load the run's robots are"
                    + " disconnected and the new run starts when its robots connect."})
final class ControlCommand implements Callable<Integer> {
    /** The id of the one request the command sends. */
    private static final long ID = 1;

    @Spec
    CommandSpec spec;

    @Mixin
    ViewerPortOptions at;

    @Mixin
    SecretOption secret;

    @Option(names = "--timeout", defaultValue = "60", paramLabel = "SECONDS",
            description = "the longest wait for the answer (a step N answers once its steps are run); default"
                    + " ${DEFAULT-VALUE}")
    int timeoutSeconds;

    @Parameters(index = "0", paramLabel = "OPERATION", description = "pause, resume, step, stop, pace, move, remove, restart, load or status")
    String op;

    @Parameters(index = "1..*", paramLabel = "ARG", description = "the operation's arguments")
    List<String> args = List.of();

    /** Prints the run's line, then a tab-separated table of the robots with a heading. */
    private void printStatus(RunStatus status) {
        PrintWriter out = spec.commandLine().getOut();
        out.println(RobotRows.runLine(status));
        out.println(String.join("\t", RobotRows.COLUMNS));
        for (List<String> row : RobotRows.of(status)) {
            out.println(String.join("\t", row));
        }
        out.flush();
    }

    @Override
    public Integer call() {
        if (timeoutSeconds < 1 || timeoutSeconds > 3600) {
            throw new ParameterException(spec.commandLine(), "--timeout: from 1 to 3600 seconds, got " + timeoutSeconds);
        }
        if (args.size() > ControlRequest.MAX_ARGS) {
            throw new ParameterException(spec.commandLine(), "at most " + ControlRequest.MAX_ARGS
                    + " arguments, got " + args.size());
        }
        String token = ControlConnection.token(spec, secret, at);
        try {
            if (op.equals("status") && args.isEmpty()) {
                printStatus(ControlConnection.exchange(at, "control", token, timeoutSeconds * 1000, ControlClient::status));
                return 0;
            }
            ControlReply reply = ControlConnection.exchange(at, "control", token, timeoutSeconds * 1000, c -> {
                c.send(new ControlRequest(ID, op, args));
                return c.answer(ControlReply.class, r -> r.id() == ID);
            });
            if (reply.ok()) {
                spec.commandLine().getOut().println(reply.text());
                return 0;
            }
            spec.commandLine().getErr().println("robosim control: refused: " + reply.text());
            return 1;
        } catch (SocketTimeoutException e) {
            spec.commandLine().getErr().println("robosim control: no answer within " + timeoutSeconds + " s (--timeout);"
                    + " the Environment may still carry the request out");
            return 1;
        } catch (ControlClient.NoAnswerException e) {
            spec.commandLine().getErr().println("robosim control: " + e.getMessage());
            return 1;
        } catch (IOException e) {
            spec.commandLine().getErr().println("robosim control: cannot reach the Environment at " + at.host + ":"
                    + at.port() + ": " + e.getMessage());
            return 1;
        }
    }
}
