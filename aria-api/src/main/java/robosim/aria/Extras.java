package robosim.aria;

/**
 * What {@link ArRobot} keeps of the calls that override what the robot reports, as ARIA's
 * {@code ArRobot} keeps them (ArRobot.cpp): the charge state and the charger's power once a program
 * set them ({@code setChargeState}, {@code setIsChargerPowerGood}), the state-of-charge thresholds,
 * whether IO packets were requested, the state reflection's refresh time, and which of
 * ARIA's logging toggles are on.
 */
final class Extras {
    /** ARIA's default state-reflection refresh time, ms. */
    static final int DEFAULT_REFRESH_MS = 500;

    volatile ArRobot.ChargeState chargeState;
    volatile Boolean chargerPowerGood;
    volatile double stateOfChargeLow;
    volatile double stateOfChargeShutdown;
    volatile boolean ioRequested;
    volatile int refreshMs = DEFAULT_REFRESH_MS;
    volatile boolean logMovementSent;
    volatile boolean logMovementReceived;
    volatile boolean logVelocitiesReceived;
    volatile boolean logSipContents;
    volatile boolean packetsReceivedTracking;
    volatile boolean packetsSentTracking;
}
