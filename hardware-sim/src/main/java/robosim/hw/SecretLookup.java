package robosim.hw;

import java.util.function.Supplier;
import robosim.protocol.RunSecret;

/**
 * The run secret a robot presents, looked up in the places {@link RunSecret#find} looks the moment
 * the robot's connection is open rather than before it tries to connect: an Environment writes its
 * secret before it listens, so a robot started first and connected once the Environment listens
 * finds this run's secret, not none or an earlier run's. It keeps the secret it gave, to tell
 * whether a refusal may clear ({@link RunSecret#mayClear}).
 */
final class SecretLookup implements Supplier<String> {
    private final String host;
    private final int port;
    private volatile String given;

    /**
     * @param host  the Environment's host (a secret file is read only for a loopback host)
     * @param port  its robot port
     * @param first the secret found before connecting, given if nothing is found later
     */
    SecretLookup(String host, int port, String first) {
        this.host = host;
        this.port = port;
        this.given = first;
    }

    /** @return the secret found now, or the one found before connecting if none is found now */
    @Override
    public String get() {
        String now = RunSecret.findAgain(host, port);
        if (now != null) {
            given = now;
        }
        return given;
    }

    /** @return the secret last given */
    String given() {
        return given;
    }
}
