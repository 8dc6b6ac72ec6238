package robosim.panel.model;

import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Where a started Environment listens, read from the line {@code robosim env} prints once bound
 * ({@code Environment: world W, robots on HOST:PORT, viewers on HOST:PORT}), since with port 0 the
 * ports are known only then.
 *
 * @param world      the world's name
 * @param robotHost  the robots' address
 * @param robotPort  the robot port
 * @param viewerHost the viewers' address
 * @param viewerPort the viewer port
 */
public record EnvironmentLine(String world, String robotHost, int robotPort, String viewerHost, int viewerPort) {
    private static final Pattern LINE = Pattern.compile(
            "Environment: world (.+), robots on (\\S+):(\\d{1,5}), viewers on (\\S+):(\\d{1,5})");

    /**
     * @param line a line of the Environment's output
     * @return where it listens, if this is the line that says so
     */
    public static Optional<EnvironmentLine> parse(String line) {
        Matcher m = LINE.matcher(line.strip());
        if (!m.matches()) {
            return Optional.empty();
        }
        return Optional.of(new EnvironmentLine(m.group(1), m.group(2), Integer.parseInt(m.group(3)), m.group(4),
                Integer.parseInt(m.group(5))));
    }

    /**
     * @return the host a client on this machine connects to: loopback when the Environment listens on
     *         every address
     */
    public String clientHost() {
        return viewerHost.equals("0.0.0.0") || viewerHost.equals("[::]") || viewerHost.equals("::")
                ? "127.0.0.1" : viewerHost;
    }
}
