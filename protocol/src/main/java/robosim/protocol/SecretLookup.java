package robosim.protocol;

import java.util.function.Supplier;

/**
 * The run secret a client presents, looked up in the places {@link RunSecret#find} looks each
 * time the client's connection is open, rather than once before it tries to connect: an
 * Environment writes its secret before it listens, so a client started first and connected once
 * the Environment listens finds this run's secret, not none or an earlier run's. It keeps the
 * secret it gave last, to tell whether a refusal may clear ({@link #clears}).
 */
public final class SecretLookup implements Supplier<String> {
    private final String host;
    private final int port;
    private volatile String given;

    /**
     * @param host  the Environment's host (a secret file is read only for a loopback host)
     * @param port  the port the client connects to
     * @param first the secret found before connecting, given if nothing is found later
     */
    public SecretLookup(String host, int port, String first) {
        this.host = host;
        this.port = port;
        this.given = first;
    }

    /** @return the secret found now, or the one given before if none is found now */
    @Override
    public String get() {
        String now = RunSecret.findAgain(host, port);
        if (now != null) {
            given = now;
        }
        return given;
    }

    /** @return the secret last given */
    public String given() {
        return given;
    }

    /**
     * @param reason the Environment's refusal of the secret last given
     * @return whether to try again: {@link RunSecret#mayClear} with the secret found now
     */
    public boolean clears(String reason) {
        return clears(reason, given);
    }

    /**
     * @param reason    the Environment's refusal
     * @param presented the secret the refused hello presented (another's, such as a shared link's)
     * @return whether to try again: {@link RunSecret#mayClear} with the secret found now
     */
    public boolean clears(String reason, String presented) {
        return RunSecret.mayClear(reason, presented, RunSecret.findAgain(host, port));
    }
}
