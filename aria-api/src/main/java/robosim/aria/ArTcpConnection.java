package robosim.aria;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.NoRouteToHostException;
import java.net.Socket;
import java.net.UnknownHostException;

/**
 * ARIA's {@code ArTcpConnection}: a Pioneer robot server reached over TCP (RoboSim's Pioneer port,
 * MobileSim, a robot behind a serial-to-TCP bridge). {@link #open(String, int)} checks that
 * something answers there, as ARIA's opens its socket; a robot given the connection
 * ({@link ArRobot#setDeviceConnection}) then connects to that address when it connects.
 */
public class ArTcpConnection extends ArDeviceConnection {
    /** The network failed. */
    public static final int OPEN_NET_FAIL = 1;
    /** The host is not known. */
    public static final int OPEN_BAD_HOST = 2;
    /** No route to the host. */
    public static final int OPEN_NO_ROUTE = 3;
    /** Nothing listens on the port. */
    public static final int OPEN_CON_REFUSED = 4;
    /** How long opening waits for an answer, ms. */
    private static final int OPEN_TIMEOUT_MS = 5000;

    private volatile String host = "localhost";
    private volatile int port = ArRobotConnector.DEFAULT_PORT;

    /**
     * @param hostName the host; null for localhost
     * @param tcpPort  the port
     */
    public void setPort(String hostName, int tcpPort) {
        host = hostName == null ? "localhost" : hostName;
        port = tcpPort;
    }

    /** @return the host */
    public String getHost() {
        return host;
    }

    /** @return the port */
    public int getPort() {
        return port;
    }

    /**
     * @param hostName the host; null for localhost
     * @param tcpPort  the port
     * @return 0 if something answers there, else one of the {@code OPEN_} values
     */
    public int open(String hostName, int tcpPort) {
        setPort(hostName, tcpPort);
        return open();
    }

    /** @return 0 if something answers at the address set, else one of the {@code OPEN_} values */
    public int open() {
        if (port < 1 || port > 65535) {
            status = STATUS_OPEN_FAILED;
            return OPEN_CON_REFUSED;
        }
        try (Socket probe = new Socket()) {
            probe.connect(new InetSocketAddress(host, port), OPEN_TIMEOUT_MS);
            status = STATUS_OPEN;
            return 0;
        } catch (UnknownHostException e) {
            status = STATUS_OPEN_FAILED;
            return OPEN_BAD_HOST;
        } catch (NoRouteToHostException e) {
            status = STATUS_OPEN_FAILED;
            return OPEN_NO_ROUTE;
        } catch (ConnectException e) {
            status = STATUS_OPEN_FAILED;
            return OPEN_CON_REFUSED;
        } catch (IOException e) {
            status = STATUS_OPEN_FAILED;
            return e.getMessage() != null && e.getMessage().contains("Unresolved") ? OPEN_BAD_HOST : OPEN_NET_FAIL;
        }
    }

    @Override
    public boolean openSimple() {
        return open() == 0;
    }

    /**
     * @param hostName the host; null for localhost
     * @param tcpPort  the port
     * @return whether something answers there (ARIA's {@code openSimple} after {@code setPort})
     */
    public boolean openSimple(String hostName, int tcpPort) {
        return open(hostName, tcpPort) == 0;
    }

    @Override
    public String getOpenMessage(int messageNumber) {
        return switch (messageNumber) {
            case OPEN_NET_FAIL -> "Network failed.";
            case OPEN_BAD_HOST -> "Could not find host.";
            case OPEN_NO_ROUTE -> "No route to host.";
            case OPEN_CON_REFUSED -> "Connection refused.";
            default -> "";
        };
    }

    @Override
    public String getPortName() {
        return host + ":" + port;
    }

    @Override
    public String getPortType() {
        return "tcp";
    }

    @Override
    String host() {
        return host;
    }

    @Override
    int port() {
        return port;
    }
}
