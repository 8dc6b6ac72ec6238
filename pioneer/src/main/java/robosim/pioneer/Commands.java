package robosim.pioneer;

import java.util.Map;

/**
 * The client commands' numbers and argument types, as ARIA's {@code ArCommands} numbers them, the
 * server packets' IDs, and the packets a client sends.
 */
public final class Commands {
    /** An integer argument that is zero or positive. */
    public static final int ARG_INT = 0x3B;
    /** An integer argument that is negative: the magnitude follows. */
    public static final int ARG_NEGINT = 0x1B;
    /** A string argument: a length byte and the bytes follow. */
    public static final int ARG_STRING = 0x2B;

    /** The first handshake packet; after the handshake, the keep-alive. */
    public static final int SYNC0 = 0;
    /** Keeps the link alive (the same ID as {@link #SYNC0}). */
    public static final int PULSE = 0;
    /** The second handshake packet; after the handshake, OPEN. */
    public static final int SYNC1 = 1;
    /** Starts the status packets. */
    public static final int OPEN = 1;
    /** The third handshake packet, answered with the robot's name, class and subclass. */
    public static final int SYNC2 = 2;
    /** Ends the connection. */
    public static final int CLOSE = 2;
    /** Sets the sonar polling sequence. */
    public static final int POLLING = 3;
    /** Enables (1) or disables (0) the motors. */
    public static final int ENABLE = 4;
    /** Sets the translational acceleration (positive) or deceleration (negative), mm/s². */
    public static final int SETA = 5;
    /** Sets the maximum translational velocity, mm/s. */
    public static final int SETV = 6;
    /** Resets the odometry to (0, 0, 0). */
    public static final int SETO = 7;
    /** Moves a distance, mm. */
    public static final int MOVE = 8;
    /** Rotates at a velocity, degrees/s (the same as RVEL). */
    public static final int ROTATE = 9;
    /** Sets the maximum rotational velocity, degrees/s. */
    public static final int SETRV = 10;
    /** Sets the translational velocity, mm/s. */
    public static final int VEL = 11;
    /** Turns to an absolute heading, degrees. */
    public static final int HEAD = 12;
    /** Turns by an angle, degrees. */
    public static final int DHEAD = 13;
    /** Plays a sound sequence (logged by a simulator). */
    public static final int SAY = 15;
    /** Asks for a configuration packet. */
    public static final int CONFIG = 18;
    /** Asks for encoder packets. */
    public static final int ENCODER = 19;
    /** Sets the rotational velocity, degrees/s. */
    public static final int RVEL = 21;
    /** Sets the rotational acceleration (positive) or deceleration (negative), degrees/s². */
    public static final int SETRA = 23;
    /** Enables (1) or disables (0) the sonar. */
    public static final int SONAR = 28;
    /** Stops the robot. */
    public static final int STOP = 29;
    /** Sets the wheel velocities: the argument's high byte left, low byte right, in units of the Vel2Divisor. */
    public static final int VEL2 = 32;
    /** A gripper command. */
    public static final int GRIPPER = 33;
    /** The argument of the gripper command before it (GRIP_PRESSURE, LIFT_CARRY), as ARIA's GRIPPERVAL. */
    public static final int GRIPPERVAL = 36;
    /**
     * Asks for gripper packets ({@link #GRIPPER_PACKET}): 0 none, 1 one, 2 one every cycle, as ARIA's
     * GRIPPERPACREQUEST. The older simulator's laser took the same number for the field of view's end.
     */
    public static final int GRIPPERPACREQUEST = 37;
    /** Asks for IO packets. */
    public static final int IOREQUEST = 40;
    /** Sets whether bumping stalls the robot: 0 no, 1 front, 2 rear, 3 both. */
    public static final int BUMPSTALL = 44;
    /** Stops at once, overriding the deceleration. */
    public static final int ESTOP = 55;
    /** Asks for battery information packets. */
    public static final int BATTERYINFO = 62;
    /** Sets the lateral velocity, mm/s. */
    public static final int LATVEL = 110;
    /** Moves the robot in the simulator to a true pose: three 32-bit integers x, y (mm), th (degrees). */
    public static final int SIM_SET_POSE = 224;
    /** Moves the robot back to its start pose and resets its odometry. */
    public static final int SIM_RESET = 225;
    /** Starts (1: 0x60 packets, 2: extended 0x61 packets) or stops (0) the simulated laser. */
    public static final int SIM_LRF_ENABLE = 230;
    /** Sets the simulated laser's first reading's angle, degrees from its heading. */
    public static final int SIM_LRF_SET_FOV_START = 231;
    /** Sets the simulated laser's last reading's angle, degrees from its heading. */
    public static final int SIM_LRF_SET_FOV_END = 232;
    /** Sets the degrees between the simulated laser's readings. */
    public static final int SIM_LRF_SET_RES = 233;
    /** A simulator meta-command. */
    public static final int SIM_CTRL = 236;
    /** Asks for a SIMSTAT packet (1: one, 2: continuous, 0: stop). */
    public static final int SIM_STAT = 237;
    /** A message for the simulator's log. */
    public static final int SIM_MESSAGE = 238;
    /** Ends the simulator. */
    public static final int SIM_EXIT = 239;

    /** The server's configuration reply. */
    public static final int CONFIG_PACKET = 0x20;
    /** The server's status packet, robot stopped. */
    public static final int SIP_STOPPED = 0x32;
    /** The server's status packet, robot moving. */
    public static final int SIP_MOVING = 0x33;
    /** The simulated laser's packet. */
    public static final int LASER_PACKET = 0x60;
    /** The simulated laser's extended packet. */
    public static final int LASER_EXTENDED_PACKET = 0x61;
    /** The simulator's status packet. */
    public static final int SIMSTAT_PACKET = 0x62;
    /** The gripper's packet, the answer to GRIPPERPACREQUEST. */
    public static final int GRIPPER_PACKET = 0xE0;

    private static final Map<Integer, String> NAMES = Map.ofEntries(
            Map.entry(PULSE, "PULSE"), Map.entry(OPEN, "OPEN"), Map.entry(CLOSE, "CLOSE"),
            Map.entry(POLLING, "POLLING"), Map.entry(ENABLE, "ENABLE"), Map.entry(SETA, "SETA"),
            Map.entry(SETV, "SETV"), Map.entry(SETO, "SETO"), Map.entry(MOVE, "MOVE"), Map.entry(ROTATE, "ROTATE"),
            Map.entry(SETRV, "SETRV"), Map.entry(VEL, "VEL"), Map.entry(HEAD, "HEAD"), Map.entry(DHEAD, "DHEAD"),
            Map.entry(SAY, "SAY"), Map.entry(CONFIG, "CONFIG"), Map.entry(ENCODER, "ENCODER"),
            Map.entry(RVEL, "RVEL"), Map.entry(SETRA, "SETRA"), Map.entry(SONAR, "SONAR"), Map.entry(STOP, "STOP"),
            Map.entry(VEL2, "VEL2"), Map.entry(GRIPPER, "GRIPPER"), Map.entry(GRIPPERVAL, "GRIPPERVAL"),
            Map.entry(GRIPPERPACREQUEST, "GRIPPERPACREQUEST"), Map.entry(IOREQUEST, "IOREQUEST"),
            Map.entry(BUMPSTALL, "BUMPSTALL"), Map.entry(ESTOP, "ESTOP"), Map.entry(BATTERYINFO, "BATTERYINFO"),
            Map.entry(LATVEL, "LATVEL"), Map.entry(SIM_SET_POSE, "SIM_SET_POSE"), Map.entry(SIM_RESET, "SIM_RESET"),
            Map.entry(SIM_LRF_ENABLE, "SIM_LRF_ENABLE"), Map.entry(SIM_LRF_SET_FOV_START, "SIM_LRF_SET_FOV_START"),
            Map.entry(SIM_LRF_SET_FOV_END, "SIM_LRF_SET_FOV_END"), Map.entry(SIM_LRF_SET_RES, "SIM_LRF_SET_RES"),
            Map.entry(SIM_CTRL, "SIM_CTRL"), Map.entry(SIM_STAT, "SIM_STAT"), Map.entry(SIM_MESSAGE, "SIM_MESSAGE"),
            Map.entry(SIM_EXIT, "SIM_EXIT"));

    private Commands() {
    }

    /**
     * @param id a client command's number (server packets' IDs overlap them and are named by their readers)
     * @return its name ({@code PULSE}, {@code VEL}, ...), or {@code unknown}
     */
    public static String name(int id) {
        return NAMES.getOrDefault(id, "unknown");
    }

    /**
     * @param command a command number
     * @return the command without an argument
     */
    public static PioneerPacket com(int command) {
        return PioneerPacket.of(command);
    }

    /**
     * @param command  a command number
     * @param argument its integer argument, −65535 to 65535
     * @return the command with an integer argument, as ARIA's {@code comInt} sends it
     */
    public static PioneerPacket comInt(int command, int argument) {
        return new PacketBuilder(command).intArgument(argument).build();
    }

    /**
     * @param command a command number
     * @param high    the argument's high byte
     * @param low     the argument's low byte
     * @return the command with two bytes packed into one signed 16-bit argument, as ARIA's
     *         {@code com2Bytes} sends it (VEL2: high left, low right)
     */
    public static PioneerPacket com2Bytes(int command, int high, int low) {
        return comInt(command, (short) ((high & 0xff) << 8 | low & 0xff));
    }

    /**
     * @param command  a command number
     * @param argument its string argument, at most 199 bytes of Latin-1
     * @return the command with a string argument, as ARIA's {@code comStr} sends it
     */
    public static PioneerPacket comStr(int command, String argument) {
        return new PacketBuilder(command).stringArgument(argument).build();
    }

    /**
     * @param x  mm
     * @param y  mm
     * @param th degrees
     * @return SIM_SET_POSE, as ARIA's {@code ArSimUtil} sends it: an unused byte and three 32-bit integers
     */
    public static PioneerPacket simSetPose(int x, int y, int th) {
        return new PacketBuilder(SIM_SET_POSE).u8(0).i32(x).i32(y).i32(th).build();
    }
}
