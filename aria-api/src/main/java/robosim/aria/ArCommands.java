package robosim.aria;

/**
 * ARIA's {@code ArCommands}: the numbers of the Pioneer's client commands (ArCommands.h), for
 * {@link ArRobot#comInt}, {@link ArRobot#com} and the like, as ARIA programs send them directly
 * ({@code robot.comInt(ArCommands.SOUNDTOG, 0)}). {@link ArRobot#comInt} says which it simulates.
 */
public final class ArCommands {
    /** Keeps the connection alive. */
    public static final int PULSE = 0;
    /** Starts the controller. */
    public static final int OPEN = 1;
    /** Closes the connection. */
    public static final int CLOSE = 2;
    /** Sets the sonar polling sequence. */
    public static final int POLLING = 3;
    /** Enables (1) or disables (0) the motors. */
    public static final int ENABLE = 4;
    /** Sets the translational acceleration (positive) or deceleration (negative), mm/s². */
    public static final int SETA = 5;
    /** Sets the maximum translational velocity, mm/s. */
    public static final int SETV = 6;
    /** Resets the odometry to 0, 0, 0. */
    public static final int SETO = 7;
    /** Moves this far, mm. */
    public static final int MOVE = 8;
    /** Rotates at this velocity, deg/s (the original's). */
    public static final int ROTATE = 9;
    /** Sets the maximum rotational velocity, deg/s. */
    public static final int SETRV = 10;
    /** Sets the translational velocity, mm/s. */
    public static final int VEL = 11;
    /** Turns to this heading, degrees. */
    public static final int HEAD = 12;
    /** Turns by this much, degrees. */
    public static final int DHEAD = 13;
    /** Plays a tune (a string). */
    public static final int SAY = 15;
    /** Requests joystick packets. */
    public static final int JOYINFO = 17;
    /** Requests a configuration packet. */
    public static final int CONFIG = 18;
    /** Requests encoder packets. */
    public static final int ENCODER = 19;
    /** Sets the rotational velocity's direction. */
    public static final int SETRVDIR = 20;
    /** Sets the rotational velocity, deg/s. */
    public static final int RVEL = 21;
    /** Turns by this much from the controller's heading, degrees. */
    public static final int DCHEAD = 22;
    /** Sets the rotational acceleration (positive) or deceleration (negative), deg/s². */
    public static final int SETRA = 23;
    /** Enables (1) or disables (0) the sonar. */
    public static final int SONAR = 28;
    /** Stops the robot. */
    public static final int STOP = 29;
    /** Sets the digital outputs. */
    public static final int DIGOUT = 30;
    /** Sets the wheels' velocities: left in the high byte, right in the low, in 2 cm/s. */
    public static final int VEL2 = 32;
    /** A gripper command. */
    public static final int GRIPPER = 33;
    /** Selects the analog port. */
    public static final int ADSEL = 35;
    /** The gripper's value. */
    public static final int GRIPPERVAL = 36;
    /** Requests gripper packets. */
    public static final int GRIPPERPACREQUEST = 37;
    /** Requests IO packets. */
    public static final int IOREQUEST = 40;
    /** Sends to the PTU. */
    public static final int PTUPOS = 41;
    /** Sends to the second serial port. */
    public static final int TTY2 = 42;
    /** Reads from the second serial port. */
    public static final int GETAUX = 43;
    /** Stops at a bump. */
    public static final int BUMPSTALL = 44;
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
    public static final int ESTOP = 55;
    /** The stall's setting. */
    public static final int ESTALL = 56;
    /** Requests gyro packets. */
    public static final int GYRO = 58;
    /** Battery information. */
    public static final int BATTERYINFO = 62;
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
