package robosim.cli;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine.Option;
import robosim.env.net.Access;
import robosim.env.net.Limits;
import robosim.env.net.ServerOptions;
import robosim.protocol.RunSecret;

/** {@code env}'s run secret and caps: who may use the ports, and how many of what. */
final class AccessOptions {
    @Option(names = "--token", paramLabel = "SECRET", description = OptionTexts.TOKEN + "; 16 to 128 letters, digits,"
            + " '-' or '_'; default: a new random one each run")
    String token;

    @Option(names = "--no-token", description = "run without a secret: anyone on this machine may join, watch and"
            + " change the run; only with a loopback --bind")
    boolean noToken;

    @Option(names = "--token-file", paramLabel = "FILE", description = "write the secret to FILE (readable only by you)"
            + " instead of ~/.robosim/tokens/PORT for each port")
    Path tokenFile;

    @Option(names = "--public-view", description = "let viewers watch without the secret (they can never change the run)")
    boolean publicView;

    @Option(names = "--max-pending", defaultValue = "" + Limits.MAX_PENDING, paramLabel = "N",
            description = "connections that have not said hello yet, both ports together; default ${DEFAULT-VALUE}")
    int maxPending;

    @Option(names = "--max-robots", defaultValue = "" + Limits.MAX_ROBOTS, paramLabel = "N",
            description = "robots in a run; a world with more is refused; default ${DEFAULT-VALUE}")
    int maxRobots;

    @Option(names = "--max-viewers", defaultValue = "" + Limits.MAX_VIEWERS, paramLabel = "N",
            description = "viewers attached at once; default ${DEFAULT-VALUE}")
    int maxViewers;

    @Option(names = "--max-controls", defaultValue = "" + Limits.MAX_CONTROLS, paramLabel = "N",
            description = "control clients (robosim comms) attached at once; default ${DEFAULT-VALUE}")
    int maxControls;

    @Option(names = "--hello-deadline", defaultValue = "" + Limits.HELLO_DEADLINE_MS, paramLabel = "MS",
            description = "ms a new connection has to say hello; default ${DEFAULT-VALUE}")
    long helloDeadlineMs;

    @Option(names = "--idle-timeout", defaultValue = "" + Limits.IDLE_TIMEOUT_MS, paramLabel = "MS",
            description = "ms a viewer or control client may take nothing sent to it (a control client: send nothing)"
                    + " before it is closed; default ${DEFAULT-VALUE}")
    long idleTimeoutMs;

    @Option(names = "--viewer-budget", defaultValue = "" + (Limits.VIEWER_BUDGET >> 20), paramLabel = "MIB",
            description = "MiB all viewers' queues may hold together; past it the viewer furthest behind is dropped;"
                    + " default ${DEFAULT-VALUE}")
    long viewerBudgetMib;

    /**
     * @return the caps given
     * @throws IllegalArgumentException naming the flag, the value and the rule
     */
    Limits limits() {
        ServerOptions.requireAtLeast("--max-pending", maxPending, 1);
        ServerOptions.requireAtLeast("--max-robots", maxRobots, 1);
        ServerOptions.requireAtLeast("--max-viewers", maxViewers, 0);
        ServerOptions.requireAtLeast("--max-controls", maxControls, 0);
        ServerOptions.requireAtLeast("--hello-deadline", helloDeadlineMs, 1);
        ServerOptions.requireAtLeast("--idle-timeout", idleTimeoutMs, 1);
        ServerOptions.requireAtLeast("--viewer-budget", viewerBudgetMib, 1);
        ServerOptions.requireAtMost("--viewer-budget", viewerBudgetMib, 1L << 20);
        return new Limits(maxPending, maxRobots, maxViewers, maxControls, helloDeadlineMs, idleTimeoutMs,
                viewerBudgetMib << 20);
    }

    /**
     * @return who may use the ports: the secret given, a new one, or none with {@code --no-token}
     * @throws IllegalArgumentException if the secret given breaks the rule, or both flags are given
     */
    Access access() {
        if (noToken && (token != null || tokenFile != null)) {
            throw new IllegalArgumentException("--no-token was given with " + (token != null ? "--token" : "--token-file")
                    + ": choose one");
        }
        if (noToken) {
            return new Access(null, publicView);
        }
        if (token != null) {
            try {
                RunSecret.check(token);
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("--token: " + e.getMessage(), e);
            }
        }
        return new Access(token != null ? token : RunSecret.create(), publicView);
    }

    /**
     * Writes the secret where clients look for it and says where on {@code out}.
     *
     * @param secret the run's secret
     * @param ports  the ports listened on
     * @return the files written, to remove when the run ends
     * @throws IOException if a file cannot be written
     */
    List<Path> publish(String secret, PrintWriter out, int... ports) throws IOException {
        List<Path> files = new ArrayList<>();
        if (tokenFile != null) {
            files.add(tokenFile);
        } else {
            for (int port : ports) {
                files.add(RunSecret.fileFor(port));
            }
        }
        for (Path f : files) {
            RunSecret.write(f, secret);
        }
        out.println("Run secret: in " + String.join(" and ", files.stream().map(Path::toString).toList())
                + " (only you can read it); clients of yours on this machine find it there, others need it as $"
                + RunSecret.ENV + (tokenFile != null ? " or $" + RunSecret.FILE_ENV : ""));
        return files;
    }

    /**
     * Writes the secret for the fixed ports the Environment is about to listen on, before it listens:
     * a client that connects the moment it can then always finds this run's secret, never none or
     * an earlier run's. A port another process listens on is left alone (its file is that run's;
     * the Environment will fail to listen there anyway), and so is port 0, whose number no client
     * can know before the Environment prints it.
     *
     * @param secret the run's secret
     * @param bind   the address the Environment will listen on
     * @param ports  the ports it will listen on
     * @return the files written, to remove if the Environment cannot listen after all
     * @throws IOException if a file cannot be written
     */
    List<Path> publishAhead(String secret, String bind, int... ports) throws IOException {
        List<Path> files = new ArrayList<>();
        if (tokenFile != null) {
            return files;
        }
        for (int port : ports) {
            if (port != 0 && free(bind, port)) {
                Path f = RunSecret.fileFor(port);
                RunSecret.write(f, secret);
                files.add(f);
            }
        }
        return files;
    }

    /**
     * @return whether nothing listens on the port now. The probe binds a plain socket, which does not
     *         listen: a client that tries the port meanwhile is refused and tries again, where a
     *         listening probe would take its connection and reset it on closing
     */
    private static boolean free(String bind, int port) {
        try (Socket probe = new Socket()) {
            // past connections of an earlier run on the port (TIME_WAIT) do not count; a listener does
            probe.setReuseAddress(true);
            probe.bind(new InetSocketAddress(InetAddress.getByName(bind), port));
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    /**
     * Removes the files written, if they still hold this run's secret.
     *
     * @param files  the files
     * @param secret the run's secret
     */
    static void unpublish(List<Path> files, String secret) {
        for (Path f : files) {
            try {
                if (Files.isRegularFile(f) && Files.readString(f).strip().equals(secret)) {
                    Files.delete(f);
                }
            } catch (IOException e) {
                // the file stays: the next run on the port replaces it
            }
        }
    }
}
