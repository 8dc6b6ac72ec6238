package robosim.pioneer.server;

import java.io.Closeable;
import java.io.IOException;
import java.net.InetAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.IntConsumer;

/**
 * The Pioneer ports of a run: one per robot of the world, in the world's order, from the first port
 * on (8101, 8102, ... as MobileSim numbers them). Each serves its robot to one ARIA client at a
 * time; a robot is driven either by a program on the Environment's robot port or by an ARIA client
 * here, and the run starts when every robot is driven.
 */
public final class PioneerPorts implements Closeable {
    private final List<PioneerPort> ports = new ArrayList<>();

    private PioneerPorts() {
    }

    /**
     * Opens the ports.
     *
     * @param robots  the world's robots, in its order
     * @param options where and how they listen
     * @param envHost the Environment's host, as the bridge robots reach it
     * @param envPort its robot port
     * @param secret  the run secret the bridge robots present, or null
     * @param simExit what an allowed SIM_EXIT does with its exit code
     * @return the open ports
     * @throws IOException if a port cannot listen; the ports opened before it are closed
     */
    public static PioneerPorts open(List<ServedRobot> robots, PioneerPortOptions options, String envHost, int envPort,
                                    String secret, IntConsumer simExit) throws IOException {
        PioneerPorts all = new PioneerPorts();
        InetAddress bind = InetAddress.getByName(options.bind());
        try {
            for (int i = 0; i < robots.size(); i++) {
                int port = options.firstPort() == 0 ? 0 : options.firstPort() + i;
                if (port > 65535) {
                    throw new IOException("robot " + robots.get(i).name() + " would get Pioneer port " + port
                            + ": ports end at 65535; choose a lower --pioneer-port");
                }
                all.ports.add(new PioneerPort(robots.get(i), bind, port, options, envHost, envPort, secret, simExit));
            }
        } catch (IOException | RuntimeException e) {
            all.close();
            throw e;
        }
        return all;
    }

    /** @return each robot's name and port, in the world's order, as {@code name=port} */
    public List<String> describe() {
        List<String> out = new ArrayList<>();
        for (PioneerPort p : ports) {
            out.add(p.robot().name() + "=" + p.port());
        }
        return out;
    }

    /**
     * @param robot a robot's name
     * @return its port, or −1 if none serves it
     */
    public int portOf(String robot) {
        for (PioneerPort p : ports) {
            if (p.robot().name().equals(robot)) {
                return p.port();
            }
        }
        return -1;
    }

    /**
     * What the run report says of a robot whose ARIA client left while it was in the run and that no
     * client drove again: the Environment counts such a robot as in the run to the end (it stood
     * still there), which is not the whole truth.
     *
     * @param robot a robot's name
     * @return for example {@code its ARIA client left after step 37 (the client sent CLOSE); the
     *         robot stood still from then to the end}; empty if a client drove it to the end, or if
     *         no ARIA client brought it into the run
     */
    public Optional<String> unattended(String robot) {
        for (PioneerPort p : ports) {
            if (p.robot().name().equals(robot)) {
                return p.unattended();
            }
        }
        return Optional.empty();
    }

    /** Stops listening; the robots of attached clients leave the run. */
    @Override
    public void close() {
        for (PioneerPort p : ports) {
            p.close();
        }
    }
}
