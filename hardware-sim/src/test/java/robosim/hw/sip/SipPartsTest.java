package robosim.hw.sip;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.params.ConversionFactors;
import robosim.pioneer.Sip;
import robosim.protocol.BatteryReading;
import robosim.protocol.GripperState;
import robosim.protocol.Bumpers;
import robosim.protocol.RobotState;
import robosim.protocol.SonarReading;
import robosim.protocol.StateParts;

/**
 * The parts a SIP carries, written by one connection's parts and read back by another's, through
 * the packet's bytes.
 */
class SipPartsTest {
    private static final ConversionFactors P3DX = new ConversionFactors(0.001534, 0.485, 1, 1, 0.0056, 20);

    private static RobotState state() {
        return new RobotState(5, 500, 0, 0, 0, 0, 0, 0, 0, false, 0);
    }

    /** Writes a SIP of the state, encodes and decodes it, and reads its parts back. */
    private static StateParts roundTrip(SipParts writer, SipParts reader, RobotState state, boolean sonarOn) {
        SipFields f = new SipFields(sonarOn ? Sip.FLAG_SONARS : 0, 0, 130);
        writer.write(state, f);
        Sip sip = new Sip(false, 0, 0, 0, 0, 0, f.battery, f.stallBump, 0, f.flags, 0, f.sonar, f.anPort, 0, 0,
                f.batteryX10, 0, 0, 0, 0, -127, f.stateOfCharge);
        return reader.read(Sip.decode(sip.toPacket()), StateParts.NONE);
    }

    private static SipParts parts(int sonars) {
        return new SipParts(new SipContext(P3DX, sonars, 5000));
    }

    @Test
    void theBatteryTravelsInDecivoltsAndItsChargeInPercent() {
        SipParts writer = parts(0);
        RobotState s = state().with(BatteryReading.PART, new BatteryReading(12.87, 99.6));
        SipFields f = new SipFields(0, 0, 130);
        writer.write(s, f);
        assertEquals(129, f.battery, "BATTERY, one byte");
        assertEquals(129, f.batteryX10, "BATTX10, two bytes");
        assertEquals(100, f.stateOfCharge);
        assertEquals(new BatteryReading(12.9, 100), roundTrip(writer, parts(0), s, false).get(BatteryReading.PART));
    }

    @Test
    void aStateWithoutABatteryReadsMobileSimsThirteenVolts() {
        StateParts back = roundTrip(parts(0), parts(0), state(), false);
        assertEquals(new BatteryReading(13.0, 0), back.get(BatteryReading.PART));
    }

    @Test
    void eachBumperSectorTravelsAndComesBack() {
        for (int sector = 0; sector < Bumpers.SECTORS; sector++) {
            RobotState s = state().with(Bumpers.PART, new Bumpers(1 << sector));
            assertEquals(new Bumpers(1 << sector), roundTrip(parts(0), parts(0), s, false).get(Bumpers.PART),
                    "sector " + sector);
        }
        assertEquals(1 << 3 << 8, BumpersInSip.bits(1 << 3), "the rear centre bumper");
        assertEquals(1 << 4 | 1 << 2, BumpersInSip.sectors(0b0000_0010 << 8 | 0b0010_0000 << 8),
                "rear bumper bits are the rear sectors");
    }

    @Test
    void aRingOfTwentyFourTakesTwoSipsAndTheReaderKeepsTheWholeRing() {
        int[] ring = new int[24];
        for (int i = 0; i < ring.length; i++) {
            ring[i] = 1000 + 20 * i;
        }
        RobotState s = state().with(SonarReading.PART, new SonarReading(ring));
        SipParts writer = parts(0);
        SipParts reader = parts(24);
        int[] first = roundTrip(writer, reader, s, true).get(SonarReading.PART).ranges();
        assertEquals(1000, first[0]);
        assertEquals(5000, first[16], "not yet carried: the range before the first reading");
        assertArrayEquals(ring, roundTrip(writer, reader, s, true).get(SonarReading.PART).ranges());
        assertNull(roundTrip(writer, reader, s, false).get(SonarReading.PART), "no ring while the sonars are off");
    }

    @Test
    void theGrippersSwitchesTravelInAnportsHighByteAsAriaReadsAGenioGripper() {
        // paddles closed on an object (both paddles triggered), lift at a limit, inner beam broken
        int switches = GripperState.PADDLES_OPEN_CLEAR | GripperState.INNER_BEAM;
        RobotState s = state().with(GripperState.PART, new GripperState(switches, 10, 0.6, 1, 3));
        SipFields f = new SipFields(0, 0, 130);
        parts(0).write(s, f);
        assertEquals(switches << 8, f.anPort, "ANPORT: getAnalogPortSelected() >> 8 is the switch byte");
        SipParts reader = new SipParts(new SipContext(P3DX, 0, 5000, true));
        assertEquals(new GripperState(switches, 0, 1, 0, -1), roundTrip(parts(0), reader, s, false).get(GripperState.PART));
        assertNull(roundTrip(parts(0), parts(0), s, false).get(GripperState.PART),
                "a client whose server has no gripper reads none");
        SipFields none = new SipFields(0, 0, 130);
        parts(0).write(state(), none);
        assertEquals(0, none.anPort, "no gripper: ANPORT 0");
    }

    @Test
    void theRegistryMakesOnePartOfEachKindForAConnection() {
        assertEquals(List.of(SonarInSip.class, BumpersInSip.class, BatteryInSip.class, GripperInSip.class),
                SipParts.ALL.stream().map(k -> k.apply(new SipContext(P3DX, 0, 0)).getClass()).toList());
    }
}
