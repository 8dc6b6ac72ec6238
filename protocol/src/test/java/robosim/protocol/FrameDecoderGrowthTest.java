package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.nio.ByteBuffer;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The decoder's space for a payload grows with the bytes that arrive: a peer that announces a
 * large frame and sends little holds little memory, and a large frame split anywhere still arrives
 * whole.
 */
class FrameDecoderGrowthTest {
    private final MessageCodec codec = new MessageCodec();

    private static long allocatedByThisThread() {
        return ((com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean())
                .getThreadAllocatedBytes(Thread.currentThread().getId());
    }

    @Test
    void anAnnouncedFrameThatDoesNotComeCostsAtMostTheFirstAllocation() throws FrameException {
        FrameDecoder decoder = new FrameDecoder(codec, FrameReader.DEFAULT_MAX_FRAME);
        ByteBuffer header = ByteBuffer.allocate(14).putInt(FrameReader.DEFAULT_MAX_FRAME).put(new byte[10]).flip();

        long before = allocatedByThisThread();
        List<Message> got = decoder.decode(header);
        long allocated = allocatedByThisThread() - before;

        assertEquals(List.of(), got);
        assertTrue(decoder.midFrame());
        assertTrue(allocated < FrameDecoder.FIRST_ALLOCATION + (16 << 10),
                allocated + " bytes allocated for a 4 MiB frame of which 10 bytes came");
    }

    @Test
    void aLargeFrameSplitIntoSmallPiecesArrivesWhole() throws FrameException {
        int[] scan = new int[200_000];
        Arrays.fill(scan, 1234);
        Snapshot big = new Snapshot(7, 700, List.of(new Snapshot.RobotView("r1", 1, 2, 3, false, true, new int[0],
                1, 2, 3, scan, 1)));
        ByteBuffer frame = FrameWriter.frame(codec, big);
        assertTrue(frame.remaining() > 4 * FrameDecoder.FIRST_ALLOCATION, "the frame needs the space to grow");
        FrameDecoder decoder = new FrameDecoder(codec, FrameReader.DEFAULT_MAX_FRAME);

        Message got = null;
        while (frame.hasRemaining()) {
            ByteBuffer piece = frame.slice();
            piece.limit(Math.min(piece.remaining(), 1000));
            frame.position(frame.position() + piece.remaining());
            List<Message> done = decoder.decode(piece);
            if (!done.isEmpty()) {
                got = done.get(0);
            }
        }

        Snapshot back = (Snapshot) got;
        assertEquals(7, back.step());
        assertTrue(Arrays.equals(scan, back.robots().get(0).laser()));
    }
}
