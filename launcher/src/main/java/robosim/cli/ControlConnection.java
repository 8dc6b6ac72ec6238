package robosim.cli;

import java.io.IOException;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import robosim.panel.net.ControlClient;
import robosim.protocol.RunSecret;

/**
 * How {@code robosim comms} and {@code robosim control} reach a running Environment's viewer port:
 * the run secret found as every client finds it, then a {@link ControlClient}.
 */
final class ControlConnection {
    private ControlConnection() {
    }

    /**
     * Finds the run secret (the option, then the places {@link RunSecret#find} looks).
     *
     * @return the secret, or null when there is none to present
     * @throws ParameterException if the secret given breaks its rule
     */
    static String token(CommandSpec spec, SecretOption secret, ViewerPortOptions at) {
        try {
            String bad = secret.apply();
            if (bad != null) {
                throw new IllegalArgumentException(bad);
            }
            return RunSecret.find(null, at.host, at.port());
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
    }

    /**
     * Connects and says hello.
     *
     * @param at        where the Environment's viewer port is
     * @param name      the client's name, for the Environment's log
     * @param token     the run secret, or null
     * @param timeoutMs the longest wait for connecting and for each answer
     * @return the connection, hello said
     * @throws IOException if the Environment cannot be reached
     */
    static ControlClient open(ViewerPortOptions at, String name, String token, int timeoutMs) throws IOException {
        return ControlClient.open(at.host, at.port(), name, token, timeoutMs);
    }
}
