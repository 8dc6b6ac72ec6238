package robosim.pioneer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class PacketDecoderTest {
    private final List<PioneerPacket> packets = new ArrayList<>();
    private final List<String> drops = new ArrayList<>();
    private final PacketDecoder decoder = new PacketDecoder(new PacketDecoder.Listener() {
        @Override
        public void packet(PioneerPacket packet) {
            packets.add(packet);
        }

        @Override
        public void dropped(String reason) {
            drops.add(reason);
        }
    });

    private void feed(byte[] b) {
        decoder.feed(b, 0, b.length);
    }

    private static byte[] concat(byte[]... parts) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (byte[] p : parts) {
            out.writeBytes(p);
        }
        return out.toByteArray();
    }

    @Test
    void aPacketSplitInTheMiddleComesOutWhole() {
        byte[] vel = Commands.comInt(Commands.VEL, 300).encode();
        decoder.feed(vel, 0, 4);
        assertEquals(0, packets.size());
        decoder.feed(vel, 4, vel.length - 4);
        assertEquals(List.of(Commands.comInt(Commands.VEL, 300)), packets);
        assertEquals(0, decoder.pending());
    }

    @Test
    void garbageBeforeAPacketIsSkippedAndReported() {
        feed(concat(new byte[] {1, 2, 3, (byte) 0xFA, 9}, Commands.com(Commands.PULSE).encode()));
        assertEquals(List.of(Commands.com(Commands.PULSE)), packets);
        assertEquals(List.of("5 bytes outside any packet (no FA FB header) skipped"), drops);
    }

    @Test
    void aBadChecksumDropsThatPacketOnly() {
        byte[] bad = Commands.comInt(Commands.VEL, 300).encode();
        bad[bad.length - 1] ^= 1;
        feed(concat(bad, Commands.com(Commands.STOP).encode()));
        assertEquals(List.of(Commands.com(Commands.STOP)), packets);
        assertTrue(drops.get(0).startsWith("a packet with ID 11 and length byte 6 has checksum"), drops.toString());
    }

    @Test
    void aLengthOf255CannotSwallowTheGoodPacketsAfterIt() {
        byte[] truncated = {(byte) 0xFA, (byte) 0xFB, (byte) 0xFF, 11, 0x3B};
        ByteArrayOutputStream good = new ByteArrayOutputStream();
        for (int i = 0; i < 60; i++) {
            good.writeBytes(Commands.comInt(Commands.VEL, i).encode());
        }
        feed(concat(truncated, good.toByteArray()));
        // the bogus packet's 255 bytes end inside the good ones; its checksum fails and the good ones are found again
        assertEquals(60, packets.size());
        assertEquals(Commands.comInt(Commands.VEL, 59), packets.get(59));
        assertTrue(drops.get(0).startsWith("a packet with ID 11 and length byte 255"), drops.toString());
    }

    @Test
    void aLengthBelowThreeIsDropped() {
        feed(concat(new byte[] {(byte) 0xFA, (byte) 0xFB, 2, 0, 0}, Commands.com(Commands.OPEN).encode()));
        assertEquals(List.of(Commands.com(Commands.OPEN)), packets);
        assertEquals("a packet's length byte is 2: it counts the ID and the two checksum bytes, so it is at least 3",
                drops.get(0));
    }

    @Test
    void aFloodOfGarbageIsReportedWithoutGrowingTheBuffer() {
        byte[] junk = new byte[100_000];
        feed(junk);
        assertTrue(decoder.pending() <= 1);
        assertEquals(List.of("100000 bytes outside any packet (no FA FB header) skipped"), drops);
    }
}
