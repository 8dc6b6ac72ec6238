package robosim.protocol;

/**
 * The battery's part of a robot's state: what a Pioneer's SIP reports of it.
 *
 * @param volts         the voltage at the terminals now, under the robot's load, V
 * @param stateOfCharge the charge left, percent of full
 */
public record BatteryReading(double volts, double stateOfCharge) {
    /** Its key: absent (a robot without a battery model) reads as null. */
    public static final StatePart<BatteryReading> PART = StatePart.of("battery", BatteryReading.class);

    /** Checks the values. */
    public BatteryReading {
        if (!(volts >= 0 && volts < 100)) {
            throw new IllegalArgumentException(volts + " was supplied for the battery's volts: 0 to 100");
        }
        if (!(stateOfCharge >= 0 && stateOfCharge <= 100)) {
            throw new IllegalArgumentException(stateOfCharge + " was supplied for the battery's state of charge:"
                    + " 0 to 100 percent");
        }
    }
}
