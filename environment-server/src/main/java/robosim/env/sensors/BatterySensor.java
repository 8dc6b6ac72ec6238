package robosim.env.sensors;

import robosim.protocol.BatteryReading;
import robosim.protocol.StateParts;
import robosim.protocol.TruePose;

/**
 * The battery, always there: a Pioneer 3's three 12 V, 7.2 Ah lead-acid cells in parallel, full at
 * the start. The electronics draw {@value #IDLE_AMPS} A; the motors draw
 * {@value #AMPS_PER_METRE_PER_SECOND} A more for each m/s of the wheels' mean speed. The charge
 * drawn lowers the open-circuit voltage in a straight line from {@value #FULL_VOLTS} V full to
 * {@value #EMPTY_VOLTS} V empty, and the current of the latest step sags the voltage at the
 * terminals by {@value #RESISTANCE_OHMS} Ω times it: a robot reads a lower voltage while it drives,
 * and lower still the longer it has driven.
 */
final class BatterySensor implements Sensor {
    /** The cells' capacity, ampere-hours. */
    static final double CAPACITY_AH = 21.6;
    /** The open-circuit voltage when full, V: what MobileSim reports. */
    static final double FULL_VOLTS = 13.0;
    /** The open-circuit voltage when empty, V. */
    static final double EMPTY_VOLTS = 11.5;
    /** The pack's internal resistance, ohms. */
    static final double RESISTANCE_OHMS = 0.1;
    /** What the electronics draw, standing or driving, A. */
    static final double IDLE_AMPS = 1.0;
    /** What the motors draw per m/s of the wheels' mean speed, A. */
    static final double AMPS_PER_METRE_PER_SECOND = 2.0;

    /** Charge drawn so far, ampere-hours. */
    private double drawnAh;
    /** The current of the latest motion, A. */
    private double amps = IDLE_AMPS;

    @Override
    public void moved(Moved m) {
        if (m.dt() <= 0) {
            return;
        }
        double metresPerSecond = (Math.abs(m.leftMm()) + Math.abs(m.rightMm())) / 2 / 1000 / m.dt();
        amps = IDLE_AMPS + AMPS_PER_METRE_PER_SECOND * metresPerSecond;
        drawnAh = Math.min(CAPACITY_AH, drawnAh + amps * m.dt() / 3600);
    }

    @Override
    public StateParts report(StateParts parts, TruePose truePose) {
        double charge = 1 - drawnAh / CAPACITY_AH;
        double volts = EMPTY_VOLTS + (FULL_VOLTS - EMPTY_VOLTS) * charge - amps * RESISTANCE_OHMS;
        return parts.with(BatteryReading.PART, new BatteryReading(Math.max(0, volts), 100 * charge));
    }
}
