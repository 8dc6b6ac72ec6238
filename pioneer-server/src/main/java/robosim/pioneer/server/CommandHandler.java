package robosim.pioneer.server;

import java.util.HashSet;
import java.util.Set;
import java.util.function.Supplier;
import robosim.params.ConversionFactors;
import robosim.pioneer.Commands;
import robosim.pioneer.ConfigPacket;
import robosim.pioneer.PacketData;
import robosim.pioneer.PacketFormatException;
import robosim.pioneer.PioneerPacket;
import robosim.protocol.Command;
import robosim.protocol.RobotParameters;

/**
 * Carries out an ARIA client's commands after the handshake, as a Pioneer (and MobileSim) does:
 * motion commands become the robot's requests, with headings in the robot's own odometry frame;
 * ENABLE switches the robot's motors in the Environment, which ignores motion while they are
 * disabled and stops the robot at ENABLE 0 (the SIP's flag then comes from its state); the simulator commands move the robot, switch
 * the simulated laser and answer with status. A command the robot server does not carry out is
 * logged once and ignored; a packet whose data does not fit its command is dropped with a log line.
 */
final class CommandHandler {
    /** Commands a Pioneer takes that RoboSim does not simulate, ignored after one log line. */
    private static final Set<Integer> NOT_SIMULATED = Set.of(Commands.POLLING, Commands.ENCODER,
            Commands.IOREQUEST, Commands.LATVEL, Commands.SIM_CTRL, 26, 30, 31, 58, 92, 113);
    /** The firmware version the CONFIG reply names. */
    static final String FIRMWARE = "RoboSim";
    /**
     * The laser commands of the older simulator (SRISim), which ARIA's simulated laser still sends
     * (ArSimulatedLaser.cpp, {@code internalConnect}: 36, 37, 38, then 35 2). 36 and 37 are also
     * ARIA's GRIPPERVAL and GRIPPERPACREQUEST; see {@link #dispatch} for how the two are told apart.
     */
    static final int OLD_LRF_ENABLE = 35;
    static final int OLD_LRF_START = 36;
    static final int OLD_LRF_END = 37;
    static final int OLD_LRF_INCREMENT = 38;

    /** What a command does beyond the robot's requests. */
    interface Effects {
        /** @param c a request for the robot's next step */
        void request(Command c);

        /** @param p a packet for the client now */
        void reply(PioneerPacket p);

        /** The odometry starts again at (0, 0, 0) where the robot is (SETO). */
        void resetOdometry();

        /** The robot goes back to its start pose and its odometry to (0, 0, 0) (SIM_RESET). */
        void resetToStart();

        /** @param mode SIMSTAT packets: 0 none, 1 one, 2 every step */
        void simStat(int mode);

        /** @param reason the client ends the connection */
        void close(String reason);

        /** @param code the client asks the simulator to end, with this exit code */
        void simExit(int code);

        /**
         * Something for the Environment's log, which the client's input causes: at most a line a
         * second of each kind.
         *
         * @param kind what lines of this kind are about, for the count of those not logged
         * @param line the line
         */
        void log(String kind, Supplier<String> line);
    }

    private final String robot;
    private final ConversionFactors factors;
    private final RobotParameters params;
    private final Effects effects;
    private final LaserScan laser;
    private final OdometryFrame frame;
    private final GripperReports gripperReports;
    private final Set<Integer> loggedOnce = new HashSet<>();
    private volatile boolean sonarOn = true;
    /** GRIP_PRESSURE or LIFT_CARRY, waiting for its GRIPPERVAL; 0 for none. */
    private int gripperOpWaiting;
    private int transVelMax;
    private int rotVelMax;
    private int transAccel;
    private int transDecel;
    private int rotAccel;
    private int rotDecel;

    /**
     * @param robot   the robot's name, for log lines
     * @param params  its parameters (the laser's range)
     * @param factors its conversion factors (VEL2's divisor)
     * @param laser   its laser settings
     * @param frame   its odometry frame, for absolute headings
     * @param effects where the effects go
     */
    CommandHandler(String robot, RobotParameters params, ConversionFactors factors, LaserScan laser,
                   OdometryFrame frame, Effects effects) {
        this.robot = robot;
        this.frame = frame;
        this.params = params;
        this.factors = factors;
        this.laser = laser;
        this.effects = effects;
        this.gripperReports = new GripperReports(params.hasGripper());
        transVelMax = (int) Math.round(params.maxVelocity());
        rotVelMax = (int) Math.round(params.maxRVelocity());
        transAccel = (int) Math.round(params.transAccel());
        transDecel = (int) Math.round(params.transDecel());
        rotAccel = (int) Math.round(params.rotAccel());
        rotDecel = (int) Math.round(params.rotDecel());
    }

    /**
     * The answer to CONFIG: the robot's class and subclass, serial number {@code SIM}, its limits as
     * the parameter file gives them and as the client has set them since.
     *
     * @param name       the robot's name
     * @param sipCycleMs ms between status packets (the field holds at most 255)
     * @param watchdogMs the watchdog time
     * @return the reply
     */
    ConfigPacket config(String name, int sipCycleMs, int watchdogMs) {
        int sonars = params.sonarUnits().size();
        return new ConfigPacket(params.robotClass(), params.subclass(), "SIM",
                (int) Math.round(params.maxRVelocity()), (int) Math.round(params.maxVelocity()),
                (int) Math.round(Math.max(params.rotAccel(), params.rotDecel())),
                (int) Math.round(Math.max(params.transAccel(), params.transDecel())),
                name, Math.min(sipCycleMs, 255), params.hasGripper(), sonars > 0, sonars > 8, watchdogMs, rotVelMax, transVelMax,
                rotAccel, rotDecel, transAccel, transDecel, 0, 0, FIRMWARE);
    }

    /** @return the gripper packets the client asked for */
    GripperReports gripperReports() {
        return gripperReports;
    }

    /** @return whether the sonar is on */
    boolean sonarOn() {
        return sonarOn;
    }

    /**
     * Carries out one command.
     *
     * @param p the packet
     */
    void handle(PioneerPacket p) {
        try {
            dispatch(p, p.reader());
        } catch (PacketFormatException e) {
            effects.log("malformed commands from robot " + robot + "'s ARIA clients",
                    () -> "robot " + robot + ": dropped a malformed command: " + e.getMessage());
        }
    }

    /**
     * Carries out one command. 36 and 37 mean two things, as on MobileSim's successor, which takes
     * them as the older simulator's laser commands unless told not to (and simulates no gripper).
     * RoboSim tells them apart by what ARIA sends: 36 is GRIPPERVAL when it follows a GRIPPER
     * GRIP_PRESSURE or LIFT_CARRY (ArGripper.cpp, {@code gripPressure} and {@code liftCarry}, send
     * the two back to back), the laser's first angle otherwise; 37 is GRIPPERPACREQUEST with the
     * arguments it takes (0, 1, 2), the laser's last angle with any other (ARIA's simulated laser
     * sends the end of its field of view, 90 for a SICK LMS200).
     */
    private void dispatch(PioneerPacket p, PacketData d) {
        int id = p.id();
        switch (id) {
            case Commands.PULSE, Commands.OPEN, Commands.BATTERYINFO, Commands.CONFIG -> { }
            case Commands.CLOSE -> effects.close("the client sent CLOSE");
            case Commands.ENABLE -> effects.request(new Command.SetMotors(d.intArgument("argument") != 0));
            case Commands.SONAR -> {
                sonarOn = d.intArgument("argument") != 0;
                effects.request(new Command.SetSonar(sonarOn));
            }
            case Commands.SETV -> {
                transVelMax = (int) Math.min(Math.abs(d.intArgument("mm/s")), Math.round(params.maxVelocity()));
                effects.request(new Command.SetMaxTransVel(transVelMax));
            }
            case Commands.SETRV -> {
                rotVelMax = (int) Math.min(Math.abs(d.intArgument("deg/s")), Math.round(params.maxRVelocity()));
                effects.request(new Command.SetMaxRotVel(rotVelMax));
            }
            case Commands.SETA -> limit(d.intArgument("mm/s²"), Command.DriveLimit.TRANS_ACCEL,
                    Command.DriveLimit.TRANS_DECEL);
            case Commands.SETRA -> limit(d.intArgument("deg/s²"), Command.DriveLimit.ROT_ACCEL,
                    Command.DriveLimit.ROT_DECEL);
            case Commands.SETO -> effects.resetOdometry();
            case Commands.STOP, Commands.ESTOP -> effects.request(new Command.Stop());
            case Commands.VEL -> effects.request(new Command.SetVel(d.intArgument("mm/s")));
            case Commands.RVEL, Commands.ROTATE -> effects.request(new Command.SetRotVel(d.intArgument("deg/s")));
            case Commands.VEL2 -> {
                int v = d.intArgument("wheels");
                double div = factors.vel2Divisor();
                effects.request(new Command.SetVel2((byte) (v >> 8) * div, (byte) v * div));
            }
            case Commands.MOVE -> effects.request(new Command.Move(d.intArgument("mm")));
            case Commands.HEAD -> effects.request(new Command.SetHeading(frame.toEnvironmentHeading(d.intArgument("degrees"))));
            case Commands.DHEAD -> effects.request(new Command.SetDeltaHeading(d.intArgument("degrees")));
            case Commands.BUMPSTALL -> {
                int bumpStall = d.intArgument("argument"); // 0 none, 1 front, 2 rear, 3 both
                once(id, "robot " + robot + ": BUMPSTALL " + bumpStall + " noted; a RoboSim robot stalls on any"
                        + " contact, whatever the setting");
            }
            case Commands.SAY -> effects.log("sounds (SAY) of robot " + robot, () -> "robot " + robot
                    + " plays a sound (SAY, " + p.length() + " bytes)");
            case Commands.SIM_MESSAGE -> {
                String text = printable(d.stringArgument("message"));
                effects.log("messages (SIM_MESSAGE) of robot " + robot, () -> "robot " + robot + ": " + text);
                effects.request(new Command.Say(text));
            }
            case Commands.SIM_SET_POSE -> {
                d.u8("unused");
                effects.request(new Command.SetTruePose(d.i32("x"), d.i32("y"), d.i32("th")));
            }
            case Commands.SIM_RESET -> effects.resetToStart();
            case Commands.SIM_LRF_ENABLE, OLD_LRF_ENABLE -> {
                laser.enable(d.intArgument("mode"));
                effects.request(laser.command(params.laserMaxRange()));
            }
            case Commands.GRIPPER -> gripper(d.intArgument("gripper code"));
            case OLD_LRF_START -> {
                int v = d.intArgument("argument");
                if (gripperOpWaiting != 0) {
                    gripperValue(v);
                } else {
                    laserSetting(id, laser.setStart(v));
                }
            }
            case OLD_LRF_END -> {
                int v = d.intArgument("argument");
                if (v >= 0 && v <= 2) {
                    gripperReports.request(v);
                } else {
                    laserSetting(id, laser.setEnd(v));
                }
            }
            case Commands.SIM_LRF_SET_FOV_START -> laserSetting(id, laser.setStart(d.intArgument("degrees")));
            case Commands.SIM_LRF_SET_FOV_END -> laserSetting(id, laser.setEnd(d.intArgument("degrees")));
            case Commands.SIM_LRF_SET_RES, OLD_LRF_INCREMENT ->
                    laserSetting(id, laser.setResolution(d.intArgument("hundredths of a degree") / 100.0));
            case Commands.SIM_STAT -> effects.simStat(d.remaining() > 0 ? d.intArgument("mode") : 1);
            case Commands.SIM_EXIT -> effects.simExit(d.remaining() > 0 ? d.intArgument("exit code") : 0);
            default -> once(id, "robot " + robot + ": " + (NOT_SIMULATED.contains(id)
                    ? "command " + id + " (" + Commands.name(id) + ") is not simulated; ignored"
                    : "unknown command " + id + "; ignored") + " (said once)");
        }
    }

    /** GRIPPER: the robot's gripper operation, or the first half of one that takes a GRIPPERVAL. */
    private void gripper(int op) {
        gripperOpWaiting = 0;
        if (!params.hasGripper()) {
            once(Commands.GRIPPER, "robot " + robot + " has no gripper (its parameter file says no HasGripper);"
                    + " GRIPPER ignored (said once)");
            return;
        }
        if (op == Command.Gripper.GRIP_PRESSURE || op == Command.Gripper.LIFT_CARRY) {
            gripperOpWaiting = op;
            return;
        }
        try {
            effects.request(new Command.Gripper(op));
        } catch (IllegalArgumentException e) {
            effects.log("notes on robot " + robot + "'s commands", () -> "robot " + robot + ": GRIPPER ignored: "
                    + e.getMessage());
        }
    }

    /** GRIPPERVAL: the argument of the GRIP_PRESSURE or LIFT_CARRY before it. */
    private void gripperValue(int value) {
        int op = gripperOpWaiting;
        gripperOpWaiting = 0;
        try {
            effects.request(new Command.Gripper(op, value));
        } catch (IllegalArgumentException e) {
            effects.log("notes on robot " + robot + "'s commands", () -> "robot " + robot + ": GRIPPERVAL ignored: "
                    + e.getMessage());
        }
    }

    private void limit(int value, Command.DriveLimit accel, Command.DriveLimit decel) {
        if (value == 0) {
            return; // ARIA's 0: keep the limit as it is
        }
        Command.DriveLimit which = value > 0 ? accel : decel;
        int v = Math.abs(value);
        switch (which) {
            case TRANS_ACCEL -> transAccel = v;
            case TRANS_DECEL -> transDecel = v;
            case ROT_ACCEL -> rotAccel = v;
            case ROT_DECEL -> rotDecel = v;
            default -> throw new IllegalStateException("no drive limit " + which);
        }
        effects.request(new Command.SetDriveLimit(which, v));
    }

    private void laserSetting(int id, String adjusted) {
        if (adjusted != null) {
            once(1000 + id, "robot " + robot + ": " + adjusted);
        }
        if (laser.isOn()) {
            effects.request(laser.command(params.laserMaxRange()));
        }
    }

    private void once(int key, String line) {
        if (loggedOnce.add(key)) {
            effects.log("notes on robot " + robot + "'s commands", () -> line);
        }
    }

    private static String printable(String text) {
        return robosim.protocol.RobotHello.printable(text, 200);
    }
}
