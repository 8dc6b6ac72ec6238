package robosim.aria;

import robosim.pioneer.Commands;

/**
 * ARIA's {@code ArCommands}: the numbers of the Pioneer's client commands (ArCommands.h), for
 * {@link ArRobot#comInt}, {@link ArRobot#com} and the like, as ARIA programs send them directly
 * ({@code robot.comInt(ArCommands.SOUNDTOG, 0)}); the numbers the Pioneer protocol module knows come from
 * {@link Commands}. {@link ArRobot#comInt} says which it simulates.
 */
public final class ArCommands {
    /** Keeps the connection alive. */
    public static final int PULSE = Commands.PULSE;
    /** Starts the controller. */
    public static final int OPEN = Commands.OPEN;
    /** Closes the connection. */
    public static final int CLOSE = Commands.CLOSE;
    /** Sets the sonar polling sequence. */
    public static final int POLLING = Commands.POLLING;
    /** Enables (1) or disables (0) the motors. */
    public static final int ENABLE = Commands.ENABLE;
    /** Sets the translational acceleration (positive) or deceleration (negative), mm/s². */
    public static final int SETA = Commands.SETA;
    /** Sets the maximum translational velocity, mm/s. */
    public static final int SETV = Commands.SETV;
    /** Resets the odometry to 0, 0, 0. */
    public static final int SETO = Commands.SETO;
    /** Moves this far, mm. */
    public static final int MOVE = Commands.MOVE;
    /** Rotates at this velocity, deg/s (the original's). */
    public static final int ROTATE = Commands.ROTATE;
    /** Sets the maximum rotational velocity, deg/s. */
    public static final int SETRV = Commands.SETRV;
    /** Sets the translational velocity, mm/s. */
    public static final int VEL = Commands.VEL;
    /** Turns to this heading, degrees. */
    public static final int HEAD = Commands.HEAD;
    /** Turns by this much, degrees. */
    public static final int DHEAD = Commands.DHEAD;
    /** Plays a tune (a string). */
    public static final int SAY = Commands.SAY;
    /** Requests joystick packets. */
    public static final int JOYINFO = 17;
    /** Requests a configuration packet. */
    public static final int CONFIG = Commands.CONFIG;
    /** Requests encoder packets. */
    public static final int ENCODER = Commands.ENCODER;
    /** Sets the rotational velocity's direction. */
    public static final int SETRVDIR = 20;
    /** Sets the rotational velocity, deg/s. */
    public static final int RVEL = Commands.RVEL;
    /** Turns by this much from the controller's heading, degrees. */
    public static final int DCHEAD = 22;
    /** Sets the rotational acceleration (positive) or deceleration (negative), deg/s². */
    public static final int SETRA = Commands.SETRA;
    /** Enables (1) or disables (0) the sonar. */
    public static final int SONAR = Commands.SONAR;
    /** Stops the robot. */
    public static final int STOP = Commands.STOP;
    /** Sets the digital outputs. */
    public static final int DIGOUT = 30;
    /** Sets the wheels' velocities: left in the high byte, right in the low, in 2 cm/s. */
    public static final int VEL2 = Commands.VEL2;
    /** A gripper command. */
    public static final int GRIPPER = Commands.GRIPPER;
    /** Selects the analog port. */
    public static final int ADSEL = 35;
    /** The gripper's value. */
    public static final int GRIPPERVAL = Commands.GRIPPERVAL;
    /** Requests gripper packets. */
    public static final int GRIPPERPACREQUEST = 37;
    /** Requests IO packets. */
    public static final int IOREQUEST = Commands.IOREQUEST;
    /** Sends to the PTU. */
    public static final int PTUPOS = 41;
    /** Sends to the second serial port. */
    public static final int TTY2 = 42;
    /** Reads from the second serial port. */
    public static final int GETAUX = 43;
    /** Stops at a bump. */
    public static final int BUMPSTALL = Commands.BUMPSTALL;
    /** The TCM2 compass. */
    public static final int TCM2 = 45;
    /** Drives by the joystick. */
    public static final int JOYDRIVE = 47;
    /** Blinks while moving. */
    public static final int MOVINGBLINK = 49;
    /** The host's baud rate. */
    public static final int HOSTBAUD = 50;
    /** The first auxiliary port's baud rate. */
    public static final int AUX1BAUD = 51;
    /** The second auxiliary port's baud rate. */
    public static final int AUX2BAUD = 52;
    /** Emergency stop. */
    public static final int ESTOP = Commands.ESTOP;
    /** The stall's setting. */
    public static final int ESTALL = 56;
    /** Requests gyro packets. */
    public static final int GYRO = 58;
    /** Battery information. */
    public static final int BATTERYINFO = Commands.BATTERYINFO;
    /** The simulator's exit. */
    public static final int ENDSIM = 62;
    /** The simulator's step. */
    public static final int STEP = 64;
    /** Plays a sound. */
    public static final int SOUND = 90;
    /** Requests the sound playlist. */
    public static final int PLAYLIST = 91;
    /** Sounds on (1) or off (0): an AmigoBot's. */
    public static final int SOUNDTOG = 92;
    /** The laser's power. */
    public static final int POWER_LRF = 96;
    /** The second laser's power. */
    public static final int POWER_LRF2 = 129;

    private ArCommands() {
    }
}
