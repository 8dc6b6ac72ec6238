package robosim.cli;

import java.io.IOException;
import java.io.InterruptedIOException;
import java.net.ConnectException;
import java.util.concurrent.TimeUnit;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import robosim.panel.net.ControlClient;
import robosim.protocol.RunSecret;
import robosim.protocol.SecretLookup;

/**
 * How {@code robosim comms} and {@code robosim control} reach a running Environment's viewer port:
 * the run secret found as every client finds it, then a {@link ControlClient}.
 */
final class ControlConnection {
    /** How long to wait before connecting again while nothing listens, ms. */
    static final long RETRY_MS = 200;

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

    /** What a command does over its connection. */
    interface Exchange<T> {
        T with(ControlClient c) throws IOException;
    }

    /**
     * Connects, says hello and has the exchange done, within {@code timeoutMs}: while nothing listens
     * (an Environment starting) it connects again, and a refusal of the secret found first is tried
     * again once the secret found now is another ({@link RunSecret#mayClear}): the Environment had
     * not written its own yet. Any other refusal is final.
     *
     * @param at        where the Environment's viewer port is
     * @param name      the client's name, for the Environment's log
     * @param token     the run secret found first, or null
     * @param timeoutMs the longest wait for connecting and for each answer
     * @param exchange  what to do once connected
     * @param <T>       what it gives
     * @return what it gave
     * @throws IOException if the Environment cannot be reached, refuses, or does not answer
     */
    static <T> T exchange(ViewerPortOptions at, String name, String token, int timeoutMs, Exchange<T> exchange)
            throws IOException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        // looked up once connected: the Environment wrote its secret before it listened
        SecretLookup lookup = new SecretLookup(at.host, at.port(), token);
        while (true) {
            ControlClient c;
            try {
                c = ControlClient.open(at.host, at.port(), name, lookup, timeoutMs);
            } catch (ConnectException e) {
                if (deadline - System.nanoTime() < TimeUnit.MILLISECONDS.toNanos(RETRY_MS)) {
                    throw new ConnectException(e.getMessage() + " (tried for " + timeoutMs / 1000 + " s, --timeout)");
                }
                pause();
                continue;
            }
            try (c) {
                return exchange.with(c);
            } catch (ControlClient.NoAnswerException e) {
                if (!lookup.clears(e.getMessage()) || System.nanoTime() - deadline > 0) {
                    throw e;
                }
            }
        }
    }

    private static void pause() throws IOException {
        try {
            Thread.sleep(RETRY_MS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new InterruptedIOException("interrupted while connecting");
        }
    }
}
