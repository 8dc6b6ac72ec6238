package robosim.scout;

/**
 * The indices of the Nomad state vector, {@code long State[45]}, with the names and numbers of the
 * C library's {@code Nclient.h}. Programs written in the C style import them statically:
 * {@code import static robosim.scout.StateVector.*;} then read {@code State[STATE_SONAR_0 + i]}.
 *
 * <p>What RoboSim's Scout puts in each entry (units of the Nomad: 1/10 inch, 1/10 degree):
 * <ul>
 *   <li>{@link #STATE_SIM_SPEED}: simulated time against wall-clock time since the first step, 10
 *       being real time (20 twice as fast); the only entry that depends on the machine's speed.</li>
 *   <li>{@link #STATE_IR_0}..15: 0; the Scout has no infrared sensors.</li>
 *   <li>{@link #STATE_SONAR_0}..15: each sonar's latest firing, whole inches 0..255 (see
 *       {@link Scout#conf_sn}); 255 until it first fires.</li>
 *   <li>{@link #STATE_BUMPER}: bit i set while the body touches something in bumper sector i;
 *       six sectors of 60°, sector 0 centred dead ahead, counting counter-clockwise (bit 1 is the
 *       front-left sector, bit 3 the rear, bit 5 the front-right).</li>
 *   <li>{@link #STATE_CONF_X}, {@link #STATE_CONF_Y}: odometry position, 1/10 inch, in the frame set
 *       by {@link Scout#zr}, {@link Scout#dp} and {@link Scout#da}.</li>
 *   <li>{@link #STATE_CONF_STEER}: odometry heading, 1/10 degree, 0..3599, counter-clockwise;
 *       {@link #STATE_CONF_TURRET} repeats it (the Scout has no turret).</li>
 *   <li>{@link #STATE_VEL_RIGHT} (= {@link #STATE_VEL_TRANS}) and {@link #STATE_VEL_LEFT}
 *       (= {@link #STATE_VEL_STEER}): the wheel velocities, 1/10 inch/s; {@link #STATE_VEL_TURRET} 0.</li>
 *   <li>{@link #STATE_MOTOR_STATUS}: bit 0 set while the right wheel turns, bit 1 while the left
 *       wheel turns (the C library's translation and steering motor bits).</li>
 *   <li>{@link #STATE_LASER}, {@link #STATE_COMPASS}: 0; no laser or compass.</li>
 *   <li>{@link #STATE_ERROR}: 0, or 1 after the Environment refused a request since the last
 *       {@link Scout#gs}.</li>
 * </ul>
 */
public final class StateVector {
    /** The state vector's length. */
    public static final int NUM_STATE = 45;
    /** The number of sonars. */
    public static final int SONARS = 16;
    /** The number of infrared sensors a Nomad can have (none on a Scout). */
    public static final int INFRAREDS = 16;

    /** Simulation speed, 10 being real time. */
    public static final int STATE_SIM_SPEED = 0;
    /** The first infrared reading (16 follow from here). */
    public static final int STATE_IR_0 = 1;
    /** Infrared 1. */
    public static final int STATE_IR_1 = 2;
    /** Infrared 2. */
    public static final int STATE_IR_2 = 3;
    /** Infrared 3. */
    public static final int STATE_IR_3 = 4;
    /** Infrared 4. */
    public static final int STATE_IR_4 = 5;
    /** Infrared 5. */
    public static final int STATE_IR_5 = 6;
    /** Infrared 6. */
    public static final int STATE_IR_6 = 7;
    /** Infrared 7. */
    public static final int STATE_IR_7 = 8;
    /** Infrared 8. */
    public static final int STATE_IR_8 = 9;
    /** Infrared 9. */
    public static final int STATE_IR_9 = 10;
    /** Infrared 10. */
    public static final int STATE_IR_10 = 11;
    /** Infrared 11. */
    public static final int STATE_IR_11 = 12;
    /** Infrared 12. */
    public static final int STATE_IR_12 = 13;
    /** Infrared 13. */
    public static final int STATE_IR_13 = 14;
    /** Infrared 14. */
    public static final int STATE_IR_14 = 15;
    /** Infrared 15, the last. */
    public static final int STATE_IR_15 = 16;
    /** Sonar 0, dead ahead; sonar i is at {@code STATE_SONAR_0 + i}. */
    public static final int STATE_SONAR_0 = 17;
    /** Sonar 1. */
    public static final int STATE_SONAR_1 = 18;
    /** Sonar 2. */
    public static final int STATE_SONAR_2 = 19;
    /** Sonar 3. */
    public static final int STATE_SONAR_3 = 20;
    /** Sonar 4, to the left. */
    public static final int STATE_SONAR_4 = 21;
    /** Sonar 5. */
    public static final int STATE_SONAR_5 = 22;
    /** Sonar 6. */
    public static final int STATE_SONAR_6 = 23;
    /** Sonar 7. */
    public static final int STATE_SONAR_7 = 24;
    /** Sonar 8, behind. */
    public static final int STATE_SONAR_8 = 25;
    /** Sonar 9. */
    public static final int STATE_SONAR_9 = 26;
    /** Sonar 10. */
    public static final int STATE_SONAR_10 = 27;
    /** Sonar 11. */
    public static final int STATE_SONAR_11 = 28;
    /** Sonar 12, to the right. */
    public static final int STATE_SONAR_12 = 29;
    /** Sonar 13. */
    public static final int STATE_SONAR_13 = 30;
    /** Sonar 14. */
    public static final int STATE_SONAR_14 = 31;
    /** Sonar 15. */
    public static final int STATE_SONAR_15 = 32;
    /** The bumper sectors in contact, a bit each. */
    public static final int STATE_BUMPER = 33;
    /** Odometry x, 1/10 inch. */
    public static final int STATE_CONF_X = 34;
    /** Odometry y, 1/10 inch. */
    public static final int STATE_CONF_Y = 35;
    /** Odometry heading, 1/10 degree, 0..3599. */
    public static final int STATE_CONF_STEER = 36;
    /** The turret's heading: on a Scout, the heading again. */
    public static final int STATE_CONF_TURRET = 37;
    /** The translation velocity: on a Scout, the right wheel's, 1/10 inch/s. */
    public static final int STATE_VEL_TRANS = 38;
    /** The right wheel's velocity, 1/10 inch/s (the C library's name for a Scout). */
    public static final int STATE_VEL_RIGHT = 38;
    /** The steering velocity: on a Scout, the left wheel's, 1/10 inch/s. */
    public static final int STATE_VEL_STEER = 39;
    /** The left wheel's velocity, 1/10 inch/s (the C library's name for a Scout). */
    public static final int STATE_VEL_LEFT = 39;
    /** The turret's velocity: 0 on a Scout. */
    public static final int STATE_VEL_TURRET = 40;
    /** Which motors are turning, a bit each. */
    public static final int STATE_MOTOR_STATUS = 41;
    /** The laser's mode: 0 on a Scout. */
    public static final int STATE_LASER = 42;
    /** The compass: 0 on a Scout. */
    public static final int STATE_COMPASS = 43;
    /** The error number. */
    public static final int STATE_ERROR = 44;

    /** Bit of {@link #STATE_MOTOR_STATUS} set while the right wheel (translation motor) turns. */
    public static final long MOTOR_RIGHT = 1;
    /** Bit of {@link #STATE_MOTOR_STATUS} set while the left wheel (steering motor) turns. */
    public static final long MOTOR_LEFT = 2;

    /** The firing-order terminator of {@link Scout#conf_sn}, as in the C library. */
    public static final int ORDER_END = 255;

    private StateVector() {
    }
}
