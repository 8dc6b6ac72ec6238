package robosim.hw.sip;

import robosim.pioneer.Sip;
import robosim.protocol.BatteryReading;
import robosim.protocol.RobotState;
import robosim.protocol.StateParts;

/**
 * The battery in SIPs, as ARIA's {@code ArRobot::processMotorPacket} reads it: BATTERY, one byte of
 * decivolts on a 12 V scale; BATTX10, two bytes of decivolts, the real voltage; SOC, the state of
 * charge in percent, which ARIA counts as known once it is above 0. A robot's battery is a 12 V pack,
 * so the two voltages are the same; a reading past 99.9 V reads as 99.9.
 */
final class BatteryInSip implements SipPart {
    BatteryInSip(SipContext context) {
    }

    @Override
    public void write(RobotState state, SipFields sip) {
        BatteryReading b = state.get(BatteryReading.PART);
        if (b == null) {
            return;
        }
        int decivolts = (int) Math.round(b.volts() * 10);
        sip.battery = Math.min(decivolts, 0xff);
        sip.batteryX10 = Math.min(decivolts, 0xffff);
        sip.stateOfCharge = (int) Math.round(b.stateOfCharge());
    }

    @Override
    public StateParts read(Sip sip, StateParts parts) {
        int soc = Math.max(0, Math.min(100, sip.stateOfCharge()));
        return parts.with(BatteryReading.PART, new BatteryReading(Math.min(sip.batteryX10(), 999) / 10.0, soc));
    }
}
