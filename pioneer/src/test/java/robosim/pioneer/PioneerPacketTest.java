package robosim.pioneer;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class PioneerPacketTest {
    private static byte[] bytes(int... values) {
        byte[] b = new byte[values.length];
        for (int i = 0; i < values.length; i++) {
            b[i] = (byte) values[i];
        }
        return b;
    }

    @Test
    void sync0IsSixBytesWithAZeroChecksum() {
        assertArrayEquals(bytes(0xFA, 0xFB, 0x03, 0x00, 0x00, 0x00), Commands.com(Commands.SYNC0).encode());
    }

    @Test
    void anIntegerArgumentIsATypeByteAndALittleEndianMagnitude() {
        assertArrayEquals(bytes(0xFA, 0xFB, 0x06, 0x01, 0x3B, 0x01, 0x00, 0x02, 0x3B),
                Commands.comInt(Commands.OPEN, 1).encode());
    }

    @Test
    void aNegativeArgumentHasTheNegativeTypeByte() {
        assertArrayEquals(bytes(0xFA, 0xFB, 0x06, 0x0B, 0x1B, 0xC8, 0x00, 0xD3, 0x1B),
                Commands.comInt(Commands.VEL, -200).encode());
    }

    @Test
    void anOddLastByteIsXoredIntoTheChecksum() {
        byte[] b = bytes(0x12, 0x34, 0x56);
        assertEquals(0x1234 ^ 0x56, PioneerPacket.checksum(b, 0, 3));
    }

    @Test
    void vel2PacksLeftInTheHighByteAndRightInTheLowByte() {
        PacketData d = Commands.com2Bytes(Commands.VEL2, 5, 10).reader();
        int v = d.intArgument("arg");
        assertEquals(5, (byte) (v >> 8));
        assertEquals(10, (byte) v);
        PacketData negative = Commands.com2Bytes(Commands.VEL2, -5, 10).reader();
        int n = negative.intArgument("arg");
        assertEquals(-5, (byte) (n >> 8));
        assertEquals(10, (byte) n);
    }

    @Test
    void simSetPoseCarriesThreeFourByteIntegers() {
        PacketData d = Commands.simSetPose(-1000, 70000, -90).reader();
        d.u8("unused");
        assertEquals(-1000, d.i32("x"));
        assertEquals(70000, d.i32("y"));
        assertEquals(-90, d.i32("th"));
    }

    @Test
    void readingPastTheEndNamesThePacketAndTheField() {
        PacketFormatException e = assertThrows(PacketFormatException.class,
                () -> Commands.com(Commands.VEL).reader().intArgument("velocity"));
        assertEquals("packet 11 (VEL) of 0 data bytes ends before its velocity's type (byte 0, 1 bytes)", e.getMessage());
    }

    @Test
    void dataOverTheLengthByteIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> new PioneerPacket(1, new byte[253]));
    }

    @Test
    void aStringArgumentHasItsLength() {
        assertEquals("hello", Commands.comStr(Commands.SIM_MESSAGE, "hello").reader().stringArgument("text"));
    }
}
