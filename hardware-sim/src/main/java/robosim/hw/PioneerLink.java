package robosim.hw;

import java.io.IOException;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.params.ConversionFactors;
import robosim.params.RobotParameterFiles;
import robosim.pioneer.Commands;
import robosim.pioneer.ConfigPacket;
import robosim.pioneer.LaserPacket;
import robosim.pioneer.PacketFormatException;
import robosim.pioneer.PioneerClient;
import robosim.pioneer.PioneerPacket;
import robosim.pioneer.SimStat;
import robosim.pioneer.Sip;
import robosim.protocol.LogLimiter;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotState;
import robosim.protocol.Welcome;

/**
 * A robot's way to "the world" through a Pioneer robot server instead of the Environment: MobileSim,
 * a real Pioneer behind a serial-to-TCP bridge, or RoboSim's own Pioneer port. It connects as ARIA
 * does (SYNC0, SYNC1, SYNC2, OPEN, CONFIG) and keeps the link alive with PULSEs. It leaves the motors
 * as the server has them: as in ARIA, the program enables them ({@code enableMotors()} sends ENABLE 1),
 * and the SIP's flags say whether they are.
 * Each status packet (SIP) becomes one step, in real time, since the server keeps its own clock;
 * {@link SipToState} and {@link CommandToPackets} translate each way. A server silent for
 * {@link HardwareOptions#lostAfterMs()} is lost, as the Environment is on a {@link SocketLink}.
 */
public final class PioneerLink extends ReleasedOnClose {
    private static final Logger LOG = Logger.getLogger(PioneerLink.class.getName());
    /** A SIP cycle the CONFIG reply leaves out is a Pioneer's 100 ms. */
    private static final int DEFAULT_CYCLE_MS = 100;

    private final String host;
    private final int port;
    private final HardwareOptions options;
    private final boolean virtualThreads;
    private volatile PioneerClient client;
    private SipToState states;
    private CommandToPackets commands;
    private long openedNanos;

    /**
     * @param host    the robot server's host
     * @param port    its port
     * @param options timeouts: to connect and be answered, and the silence after which the server is lost
     */
    public PioneerLink(String host, int port, HardwareOptions options) {
        this(host, port, options, RobotThreads.virtual());
    }

    /**
     * @param host           the robot server's host
     * @param port           its port
     * @param options        timeouts
     * @param virtualThreads whether its reader is a virtual thread where the JDK allows (a runtime's choice)
     */
    PioneerLink(String host, int port, HardwareOptions options, boolean virtualThreads) {
        super(() -> { });
        if (port <= 0 || port > 65535) {
            throw new IllegalArgumentException(port + " was supplied for the Pioneer server's port: a port is 1 to 65535");
        }
        this.host = host;
        this.port = port;
        this.options = options;
        this.virtualThreads = virtualThreads;
    }

    @Override
    public String serverRobotName() {
        PioneerClient c = client;
        return c == null || c.identity() == null ? null : c.identity().name();
    }

    @Override
    public Welcome open(RobotHello hello, StepReceiver receiver) throws IOException {
        try {
            PioneerClient c = PioneerClient.connect(host, port, options.connectTimeoutMs());
            client = c;
            ConfigPacket config = c.open(options.connectTimeoutMs());
            ConversionFactors factors = RobotParameterFiles.conversionFactorsOfSubclass(c.identity().subclass());
            LOG.info(() -> "robot " + hello.name() + " drives the " + LogLimiter.excerpt(c.identity().robotClass()) + " "
                    + LogLimiter.excerpt(c.identity().subclass()) + " '" + LogLimiter.excerpt(c.identity().name()) + "' at "
                    + environment()
                    + ", status every " + config.sipCycle() + " ms, conversion factors: " + factors.describe());
            states = new SipToState(factors, hello.parameters().sonarUnits().size(), hello.parameters().sonarMaxRange(),
                    config.hasGripper());
            commands = new CommandToPackets(factors, environment());
            c.startPulses();
            Sip first = c.nextSip(options.connectTimeoutMs());
            if (first == null) {
                throw new IOException("the robot server at " + environment() + " sent no status packet within "
                        + options.connectTimeoutMs() + " ms of OPEN" + (c.endReason() == null ? "" : ": " + c.endReason()));
            }
            openedNanos = System.nanoTime();
            RobotState state = states.state(first, 0, 0, List.of());
            int cycle = config.sipCycle() > 0 ? config.sipCycle() : DEFAULT_CYCLE_MS;
            RobotThreads.unstarted("hw-pioneer-" + hello.name(), () -> read(receiver), virtualThreads).start();
            // a robot server has no world and no run: no properties, seed 0
            return new Welcome(hello.name(), cycle, state, Map.of(), 0);
        } catch (IOException | RuntimeException e) {
            close();
            throw e;
        }
    }

    private void read(StepReceiver receiver) {
        PioneerClient c = client;
        long step = 0;
        long lastSip = System.nanoTime();
        long lostNanos = TimeUnit.MILLISECONDS.toNanos(options.lostAfterMs());
        String reason = "the link closed";
        try {
            while (!isClosed()) {
                PioneerPacket p = c.receive(Math.min(options.lostAfterMs(), 100));
                if (p == null) {
                    if (c.isClosed()) {
                        reason = c.endReason() == null ? "the connection closed" : c.endReason();
                        break;
                    }
                    if (System.nanoTime() - lastSip > lostNanos) {
                        reason = "it sent no status packet for " + options.lostAfterMs() + " ms";
                        break;
                    }
                    continue;
                }
                if (p.id() == Commands.SIP_STOPPED || p.id() == Commands.SIP_MOVING) {
                    lastSip = System.nanoTime();
                    if (isClosed()) {
                        break; // no step after close
                    }
                    long timeMs = TimeUnit.NANOSECONDS.toMillis(lastSip - openedNanos);
                    receiver.step(new RobotSensorResponse(states.state(Sip.decode(p), ++step, timeMs,
                            commands.takeErrors())));
                } else {
                    other(p);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            reason = "interrupted";
        } catch (PacketFormatException e) {
            reason = "it sent a bad packet: " + e.getMessage();
        }
        receiver.ended(RunEnd.Kind.LOST, reason);
        close();
    }

    /** The packets besides SIPs that states carry: laser scans and the true pose; the rest are skipped. */
    private void other(PioneerPacket p) {
        if (p.id() == Commands.LASER_PACKET || p.id() == Commands.LASER_EXTENDED_PACKET) {
            states.laser(LaserPacket.decode(p));
        } else if (p.id() == Commands.SIMSTAT_PACKET) {
            states.simStat(SimStat.decode(p));
        }
    }

    @Override
    public void send(long step, List<RobotRequest> requests) throws IOException {
        PioneerClient c = client;
        for (RobotRequest r : requests) {
            if (r.command() instanceof robosim.protocol.Command.ConfigureLaser l && !l.on()) {
                states.laserOff();
            } else if (r.command() instanceof robosim.protocol.Command.ReportTruePose t && !t.on()) {
                states.trueOff();
            }
            for (PioneerPacket p : commands.packets(r.command())) {
                c.send(p);
            }
        }
    }

    /** Disables the motors and closes, as ARIA leaves a robot (ENABLE 0, CLOSE). */
    @Override
    public void bye(String reason) {
        PioneerClient c = client;
        if (c != null) {
            LOG.fine(() -> "leaving the robot server at " + environment() + ": " + reason);
            c.disconnect();
        }
        close();
    }

    /** @return the robot server's host */
    public String host() {
        return host;
    }

    /** @return the robot server's port */
    public int port() {
        return port;
    }

    @Override
    public String environment() {
        return host + ":" + port;
    }

    @Override
    void closed() {
        PioneerClient c = client;
        if (c != null) {
            try {
                c.close();
            } catch (RuntimeException e) {
                LOG.log(Level.FINE, "closing", e);
            }
        }
    }
}
