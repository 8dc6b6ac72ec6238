package robosim.pioneer;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The gripper on the wire: the 0xE0 packet and the SIP's ANPORT, as ARIA's ArGripper.cpp reads them. */
class GripperPacketsTest {
    @Test
    void theGripperPacketIsThreeUnsignedBytesAfterItsId() {
        GripperPacket g = new GripperPacket(GripperPacket.GENERAL_IO, 0xb1, 10);
        byte[] wire = g.toPacket().encode();
        // FA FB, length (id + 3 data + 2 checksum), E0, type, switches, grasp time, checksum
        assertArrayEquals(new byte[] {(byte) 0xfa, (byte) 0xfb, 6, (byte) 0xe0, 2, (byte) 0xb1, 10},
                Arrays.copyOf(wire, 7));
        assertEquals(9, wire.length);
        assertEquals(g, GripperPacket.decode(g.toPacket()));
    }

    @Test
    void aValueThatIsNotAByteIsRefusedNamingTheField() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new GripperPacket(2, 256, 0));
        assertTrue(e.getMessage().startsWith("256 was supplied for the gripper packet's switches"), e.getMessage());
        assertThrows(PacketFormatException.class, () -> GripperPacket.decode(PioneerPacket.of(Commands.SIP_MOVING)));
    }

    @Test
    void anportTravelsAfterTheSonarReadingsAsAriasGetAnalogPortSelected() {
        Sip sip = new Sip(false, 0, 0, 0, 0, 0, 130, 0, 0, 0, 0, List.of(new Sip.SonarReading(3, 500)), 0x3100, 0xff,
                0xff, 130, 0, 0, 0, 0, -127, 0);
        byte[] data = sip.toPacket().data();
        // 18 bytes of motion, battery, stall, control, flags and compass, 1 count, 3 per reading: then
        // ANPORT's two bytes, low byte first
        int at = 18 + 1 + 3;
        assertEquals(0x00, data[at] & 0xff);
        assertEquals(0x31, data[at + 1] & 0xff);
        assertEquals(0x3100, Sip.decode(sip.toPacket()).anPort());
    }
}
