package robosim.hw;

import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import robosim.params.ConversionFactors;
import robosim.pioneer.Commands;
import robosim.pioneer.PioneerPacket;
import robosim.protocol.Command;

/**
 * Turns the robot's {@link Command}s into the Pioneer commands ARIA would send for them: VEL, RVEL,
 * VEL2 (in units of the Vel2Divisor), MOVE, HEAD, DHEAD, STOP, SETV, SETRV, SETA and SETRA, ENABLE, SONAR,
 * the simulated laser's commands, GRIPPER and GRIPPERVAL, SIM_MESSAGE, SIM_SET_POSE, SIM_RESET and SIM_STAT. A command the
 * protocol cannot carry (messages between robots, a find report, the heat sensor, wheel moves, the
 * pan-tilt-zoom camera and ACTS, which a real robot drives over its AUX serial port) is
 * answered with an error in the robot's next state, once for each kind, instead of being dropped in
 * silence. No sockets: the link sends what it returns.
 */
final class CommandToPackets {
    /**
     * The simulated laser's commands as ARIA's {@code ArSimulatedLaser} sends them (the older
     * simulator's numbers, which MobileSim and RoboSim's Pioneer port both take): first reading,
     * last reading (degrees from the laser's heading), resolution (hundredths of a degree), and
     * enable (2: the extended 0x61 packets, 0: off).
     */
    static final int LRF_START = 36;
    static final int LRF_END = 37;
    static final int LRF_RESOLUTION = 38;
    static final int LRF_ENABLE = 35;
    /** The protocol's integer arguments are signed 16-bit. */
    private static final int MAX_ARGUMENT = 32767;

    private final ConversionFactors factors;
    private final String server;
    private final Set<String> said = ConcurrentHashMap.newKeySet();
    private final Queue<String> errors = new ConcurrentLinkedQueue<>();

    /**
     * @param factors the robot's conversion factors (VEL2's divisor)
     * @param server  the robot server, {@code host:port}, for errors
     */
    CommandToPackets(ConversionFactors factors, String server) {
        this.factors = factors;
        this.server = server;
    }

    /**
     * @param c a command of the robot
     * @return the packets that carry it, in order; none if the protocol cannot carry it (an error
     *         then waits in {@link #takeErrors()}, the first time for its kind)
     */
    List<PioneerPacket> packets(Command c) {
        if (c instanceof Command.MoveWheels) {
            return refuse("command that moves each wheel by a distance", "MoveWheels");
        }
        if (c instanceof Command.SetAccel a) {
            return List.of(Commands.comInt(Commands.SETA, arg(a.trans())), Commands.comInt(Commands.SETA, -arg(a.trans())),
                    Commands.comInt(Commands.SETRA, arg(a.rot())), Commands.comInt(Commands.SETRA, -arg(a.rot())));
        }
        if (c instanceof Command.Motion m) {
            return List.of(motion(m));
        }
        if (c instanceof Command.SetSonar s) {
            return List.of(Commands.comInt(Commands.SONAR, s.on() ? 1 : 0));
        }
        if (c instanceof Command.ConfigureLaser l) {
            return laser(l);
        }
        if (c instanceof Command.SetSonarCycle) {
            // a Pioneer's firmware fires its ring in its own sequence: nothing to send
            return List.of();
        }
        if (c instanceof Command.Say s) {
            return List.of(Commands.comStr(Commands.SIM_MESSAGE, latin1(s.text())));
        }
        if (c instanceof Command.SetTruePose p) {
            return List.of(Commands.simSetPose((int) Math.round(p.x()), (int) Math.round(p.y()),
                    (int) Math.round(p.th())));
        }
        if (c instanceof Command.ResetToStart) {
            return List.of(Commands.com(Commands.SIM_RESET));
        }
        if (c instanceof Command.ReportTruePose r) {
            return List.of(Commands.comInt(Commands.SIM_STAT, r.on() ? 2 : 0));
        }
        if (c instanceof Command.Gripper g) {
            return gripper(g);
        }
        if (c instanceof Command.ConfigureHeatSensor) {
            return refuse("heat sensor", "ConfigureHeatSensor");
        }
        if (c instanceof Command.ReportFound) {
            return refuse("report of a find to the Environment", "ReportFound");
        }
        if (c instanceof Command.ConfigurePtz || c instanceof Command.AimPtz || c instanceof Command.TrackColors
                || c instanceof Command.BindChannel) {
            // a real camera hangs on the AUX serial port, which RoboSim's Pioneer server does not simulate
            return refuse("pan-tilt-zoom camera or ACTS colour tracking (a real camera is driven through the"
                    + " AUX serial port, which this server does not simulate)", c.getClass().getSimpleName());
        }
        if (c instanceof Command.Draw) {
            return refuse("drawings in the world's views", "Draw");
        }
        if (c instanceof Command.ReportMetric) {
            return refuse("metrics for the run's results", "ReportMetric");
        }
        if (c instanceof Command.EndRun) {
            return refuse("request to end the run", "EndRun");
        }
        return refuse("messages between robots", c.getClass().getSimpleName());
    }

    /**
     * GRIPPER with the command code, followed by GRIPPERVAL for the two codes that take a value,
     * as ARIA's ArGripper.cpp sends them.
     */
    private static List<PioneerPacket> gripper(Command.Gripper g) {
        PioneerPacket op = Commands.comInt(Commands.GRIPPER, g.op());
        if (g.op() == Command.Gripper.GRIP_PRESSURE || g.op() == Command.Gripper.LIFT_CARRY) {
            return List.of(op, Commands.comInt(Commands.GRIPPERVAL, g.value()));
        }
        return List.of(op);
    }

    /** The drive's commands that one Pioneer command carries. */
    private PioneerPacket motion(Command.Motion c) {
        if (c instanceof Command.SetVel v) {
            return Commands.comInt(Commands.VEL, arg(v.vel()));
        }
        if (c instanceof Command.SetRotVel v) {
            return Commands.comInt(Commands.RVEL, arg(v.rotVel()));
        }
        if (c instanceof Command.SetVel2 v) {
            return Commands.com2Bytes(Commands.VEL2, wheel(v.left()), wheel(v.right()));
        }
        if (c instanceof Command.Move m) {
            return Commands.comInt(Commands.MOVE, arg(m.distance()));
        }
        if (c instanceof Command.SetHeading h) {
            // a Pioneer takes an absolute heading as 0 to 359 degrees
            return Commands.comInt(Commands.HEAD, (int) Math.floorMod(Math.round(h.heading()), 360L));
        }
        if (c instanceof Command.SetDeltaHeading h) {
            return Commands.comInt(Commands.DHEAD, arg(h.delta()));
        }
        if (c instanceof Command.SetMaxTransVel v) {
            return Commands.comInt(Commands.SETV, arg(Math.abs(v.vel())));
        }
        if (c instanceof Command.SetMaxRotVel v) {
            return Commands.comInt(Commands.SETRV, arg(Math.abs(v.rotVel())));
        }
        if (c instanceof Command.SetDriveLimit l) {
            return driveLimit(l);
        }
        if (c instanceof Command.Stop) {
            return Commands.com(Commands.STOP);
        }
        if (c instanceof Command.SetMotors m) {
            return Commands.comInt(Commands.ENABLE, m.on() ? 1 : 0);
        }
        throw new IllegalArgumentException("no Pioneer command carries " + c);
    }

    /** @return the errors since the last call, in order */
    List<String> takeErrors() {
        List<String> out = new ArrayList<>();
        String e;
        while ((e = errors.poll()) != null) {
            out.add(e);
        }
        return out;
    }

    private List<PioneerPacket> laser(Command.ConfigureLaser l) {
        if (!l.on()) {
            return List.of(Commands.comInt(LRF_ENABLE, 0));
        }
        return List.of(Commands.comInt(LRF_START, -90), Commands.comInt(LRF_END, 90),
                Commands.comInt(LRF_RESOLUTION, (int) Math.round(l.increment() * 100)), Commands.comInt(LRF_ENABLE, 2));
    }

    private static PioneerPacket driveLimit(Command.SetDriveLimit l) {
        int v = arg(l.value());
        return switch (l.limit()) {
            case TRANS_ACCEL -> Commands.comInt(Commands.SETA, v);
            case TRANS_DECEL -> Commands.comInt(Commands.SETA, -v);
            case ROT_ACCEL -> Commands.comInt(Commands.SETRA, v);
            case ROT_DECEL -> Commands.comInt(Commands.SETRA, -v);
        };
    }

    private List<PioneerPacket> refuse(String what, String kind) {
        if (said.add(kind)) {
            errors.add(kind + " was not carried out: the robot server at " + server + " speaks the Pioneer protocol,"
                    + " which has no " + what + " (said once for " + kind + ")");
        }
        return List.of();
    }

    private static int arg(double v) {
        return (int) Math.max(-MAX_ARGUMENT, Math.min(MAX_ARGUMENT, Math.round(v)));
    }

    private int wheel(double mmPerSec) {
        return (int) Math.max(-128, Math.min(127, Math.round(mmPerSec / factors.vel2Divisor())));
    }

    /** SIM_MESSAGE carries at most 199 bytes of Latin-1: longer text is cut, other characters become '?'. */
    private static String latin1(String text) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < Math.min(text.length(), 199); i++) {
            char c = text.charAt(i);
            b.append(c < 256 ? c : '?');
        }
        return b.toString();
    }
}
