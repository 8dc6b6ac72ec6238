package robosim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.net.InetAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import picocli.CommandLine.Option;
import robosim.env.world.RobotSpec;
import robosim.env.world.World;
import robosim.hw.HardwareOptions;
import robosim.params.ConversionFactors;
import robosim.params.RobotParameterFiles;
import robosim.pioneer.server.PioneerPortOptions;
import robosim.pioneer.server.PioneerPorts;
import robosim.pioneer.server.ServedRobot;

/** {@code env}'s options for the Pioneer ports, where ARIA programs drive the world's robots as they drive MobileSim. */
final class PioneerOptions {
    @Option(names = "--pioneer-port", paramLabel = "PORT",
            description = "offer every robot of the world to an ARIA program (C++, Python, Java) over the Pioneer "
                    + "protocol, as MobileSim does: the first robot on PORT, the next on PORT+1, ... (MobileSim's "
                    + "first is 8101; 0 takes free ports)")
    Integer firstPort;

    @Option(names = "--pioneer-bind", defaultValue = "127.0.0.1", paramLabel = "ADDRESS",
            description = "address the Pioneer ports listen on; ARIA programs cannot present the run secret, so "
                    + "the default is loopback: ${DEFAULT-VALUE}")
    String bind;

    @Option(names = "--allow-sim-exit", description = "let an ARIA program end the run with SIM_EXIT (refused otherwise)")
    boolean allowSimExit;

    /** @return whether the Pioneer ports were asked for */
    boolean requested() {
        return firstPort != null;
    }

    /**
     * Checks the options before anything starts.
     *
     * @throws IllegalArgumentException naming the option, the value and the rule
     */
    void check() {
        if (firstPort != null && (firstPort < 0 || firstPort > 65535)) {
            throw new IllegalArgumentException(firstPort + " was supplied for --pioneer-port: a port is 0 to 65535");
        }
        if (firstPort == null && (allowSimExit || !"127.0.0.1".equals(bind))) {
            throw new IllegalArgumentException((allowSimExit ? "--allow-sim-exit" : "--pioneer-bind")
                    + " needs --pioneer-port");
        }
    }

    /**
     * Opens a port for every robot of the world and says where.
     *
     * @param world    the world
     * @param envBind  the address the Environment listens on for robots
     * @param envPort  its robot port
     * @param secret   the run secret, or null
     * @param realtime whether the whole run is paced in real time anyway
     * @param out      where to say it
     * @return the ports
     * @throws IOException if a port cannot listen
     */
    PioneerPorts open(World world, String envBind, int envPort, String secret, boolean realtime, PrintWriter out)
            throws IOException {
        List<ServedRobot> robots = new ArrayList<>();
        for (RobotSpec r : world.robots()) {
            robots.add(new ServedRobot(r.name(), r.type(), r.parameters(), factors(r), world.stepMs()));
        }
        PioneerPortOptions options = new PioneerPortOptions(bind, firstPort, allowSimExit,
                PioneerPortOptions.DEFAULT_WATCHDOG_MS, true, HardwareOptions.defaults());
        PioneerPorts ports = PioneerPorts.open(robots, options, reachable(envBind), envPort, secret, code -> {
            out.printf(Locale.ROOT, "An ARIA program sent SIM_EXIT %d: the Environment exits%n", code);
            out.flush();
            Runtime.getRuntime().exit(code);
        });
        out.printf(Locale.ROOT, "Pioneer ports on %s: %s%s%n", bind, String.join(", ", ports.describe()),
                realtime ? "" : " (steps keep real time while an ARIA program is attached)");
        if (!InetAddress.getByName(bind).isLoopbackAddress()) {
            out.println("Warning: the Pioneer ports take ARIA programs from other machines without the run secret");
        }
        return ports;
    }

    /**
     * The conversion factors of a robot's ARIA parameter file. For a file of another form, those of
     * the shipped ARIA model of its subclass, which is the file an ARIA program loads for it; ARIA's
     * defaults when there is none.
     */
    static ConversionFactors factors(RobotSpec r) {
        String file = r.parameterFile() == null ? "" : r.parameterFile().toString();
        if (file.toLowerCase(Locale.ROOT).endsWith(".p")) {
            return RobotParameterFiles.conversionFactors(file);
        }
        return RobotParameterFiles.conversionFactorsOfSubclass(r.parameters().subclass());
    }

    /** The address a bridge robot in this process reaches the Environment at. */
    private static String reachable(String envBind) throws IOException {
        InetAddress a = InetAddress.getByName(envBind);
        return a.isAnyLocalAddress() ? "127.0.0.1" : envBind;
    }
}
