package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.protocol.RecordAssert.assertDeepEquals;

import com.fasterxml.jackson.dataformat.smile.databind.SmileMapper;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.FilterInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.SequenceInputStream;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.ValueSource;
import robosim.protocol.MessageCodec.Format;

class FrameReaderTest {
    private static final MessageCodec SMILE = new MessageCodec();
    private static final MessageCodec JSON = new MessageCodec(Format.JSON);

    /** The bytes FrameWriter puts on the wire for these messages. */
    private static byte[] wire(MessageCodec codec, Message... messages) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        FrameWriter writer = new FrameWriter(out, codec);
        for (Message m : messages) {
            writer.write(m);
        }
        return out.toByteArray();
    }

    /** A hand-made frame: the given length prefix, then the given payload bytes. */
    private static byte[] frame(int length, byte[] payload) {
        byte[] f = Arrays.copyOf(new byte[] {(byte) (length >>> 24), (byte) (length >>> 16), (byte) (length >>> 8),
                (byte) length}, 4 + payload.length);
        System.arraycopy(payload, 0, f, 4, payload.length);
        return f;
    }

    private static FrameReader reader(byte[] bytes) {
        return new FrameReader(new ByteArrayInputStream(bytes), SMILE, FrameReader.DEFAULT_MAX_FRAME);
    }

    /** Hands out one byte per read, as a slow socket may. */
    private static final class TrickleInputStream extends FilterInputStream {
        int reads;

        TrickleInputStream(byte[] bytes) {
            super(new ByteArrayInputStream(bytes));
        }

        @Override
        public int read(byte[] b, int off, int len) throws IOException {
            reads++;
            return super.read(b, off, Math.min(len, 1));
        }

        @Override
        public int read() throws IOException {
            reads++;
            return super.read();
        }
    }

    @Test
    void readsAFrameArrivingOneByteAtATime() throws IOException {
        byte[] bytes = wire(SMILE, Messages.timeStep());
        TrickleInputStream in = new TrickleInputStream(bytes);

        Message m = new FrameReader(in, SMILE, FrameReader.DEFAULT_MAX_FRAME).read();

        assertDeepEquals(Messages.timeStep(), m);
        assertTrue(in.reads >= bytes.length, "the stream was read " + in.reads + " times");
    }

    @ParameterizedTest(name = "split after byte {0}")
    @ValueSource(ints = {1, 3, 4, 5, 20})
    void readsAFrameSplitAcrossTwoReads(int split) throws IOException {
        byte[] bytes = wire(SMILE, Messages.robotRequests());
        // SequenceInputStream never returns bytes of both parts from one read
        InputStream in = new SequenceInputStream(new ByteArrayInputStream(Arrays.copyOfRange(bytes, 0, split)),
                new ByteArrayInputStream(Arrays.copyOfRange(bytes, split, bytes.length)));

        Message m = new FrameReader(in, SMILE, FrameReader.DEFAULT_MAX_FRAME).read();

        assertEquals(Messages.robotRequests(), m);
    }

    @Test
    void readsFramesBackToBackInOrder() throws IOException {
        FrameReader reader = reader(wire(SMILE, Messages.robotHello(), Messages.robotRequests(), Messages.bye()));

        assertEquals(Messages.robotHello(), reader.read());
        assertEquals(Messages.robotRequests(), reader.read());
        assertEquals(Messages.bye(), reader.read());
    }

    @Test
    void readsBackToBackFramesArrivingOneByteAtATime() throws IOException {
        byte[] bytes = wire(SMILE, Messages.viewerHello(), Messages.worldDescription(), Messages.snapshot());
        FrameReader reader = new FrameReader(new TrickleInputStream(bytes), SMILE, FrameReader.DEFAULT_MAX_FRAME);

        assertEquals(Messages.viewerHello(), reader.read());
        assertDeepEquals(Messages.worldDescription(), reader.read());
        assertDeepEquals(Messages.snapshot(), reader.read());
        assertNull(reader.read());
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void readsEveryMessageTypeThatTheWriterWrote(Format format) throws IOException {
        MessageCodec codec = new MessageCodec(format);
        Message[] all = Messages.all().toArray(new Message[0]);
        FrameReader reader = new FrameReader(new ByteArrayInputStream(wire(codec, all)), codec,
                FrameReader.DEFAULT_MAX_FRAME);

        for (Message expected : all) {
            assertDeepEquals(expected, reader.read());
        }
        assertNull(reader.read());
    }

    @Test
    void emptyStreamEndsCleanly() throws IOException {
        assertNull(reader(new byte[0]).read());
    }

    @Test
    void streamEndingBetweenFramesEndsCleanly() throws IOException {
        FrameReader reader = reader(wire(SMILE, Messages.bye()));

        reader.read();

        assertNull(reader.read());
    }

    @ParameterizedTest(name = "{0} header bytes")
    @ValueSource(ints = {1, 2, 3})
    void streamEndingInsideAHeaderIsAFrameError(int headerBytes) {
        byte[] bytes = Arrays.copyOf(frame(30, new byte[30]), headerBytes);

        FrameException e = assertThrows(FrameException.class, () -> reader(bytes).read());

        assertEquals("stream ended inside a frame header", e.getMessage());
    }

    @Test
    void streamEndingInsideAPayloadIsAFrameError() {
        byte[] bytes = frame(10, new byte[] {1, 2, 3, 4});

        FrameException e = assertThrows(FrameException.class, () -> reader(bytes).read());

        assertEquals("stream ended inside a frame of 10 bytes", e.getMessage());
    }

    @Test
    void streamEndingInsideTheSecondFrameIsAFrameError() throws IOException {
        byte[] two = wire(SMILE, Messages.bye(), Messages.bye());
        FrameReader reader = reader(Arrays.copyOf(two, two.length - 1));

        assertEquals(Messages.bye(), reader.read());

        assertThrows(FrameException.class, reader::read);
    }

    @Test
    void oversizedLengthIsRejectedNamingTheLimitAndTheLength() {
        // only the header: a reader that tried to read the payload would report a truncated frame
        byte[] header = frame(101, new byte[0]);
        FrameReader reader = new FrameReader(new ByteArrayInputStream(header), SMILE, 100);

        FrameException e = assertThrows(FrameException.class, reader::read);

        assertEquals("frame of 101 bytes exceeds the limit of 100 bytes", e.getMessage());
    }

    @Test
    void hugeLengthIsRejectedAgainstTheDefaultLimit() {
        byte[] header = frame(Integer.MAX_VALUE, new byte[0]);

        FrameException e = assertThrows(FrameException.class, () -> reader(header).read());

        assertEquals("frame of 2147483647 bytes exceeds the limit of 4194304 bytes", e.getMessage());
    }

    @Test
    void frameExactlyAtTheLimitIsRead() throws IOException {
        byte[] payload = JSON.encode(new Bye("done"));
        byte[] bytes = frame(payload.length, payload);
        FrameReader reader = new FrameReader(new ByteArrayInputStream(bytes), JSON, payload.length);

        assertEquals(new Bye("done"), reader.read());
    }

    @Test
    void zeroLengthIsNotReportedAsExceedingTheLimit() {
        byte[] bytes = frame(0, new byte[] {1, 2, 3});

        FrameException e = assertThrows(FrameException.class, () -> reader(bytes).read());

        assertEquals("frame of 0 bytes: a frame holds at least 1 byte", e.getMessage());
    }

    @Test
    void negativeLengthIsRejectedAsOversized() {
        byte[] bytes = frame(-1, new byte[] {1, 2, 3});

        FrameException e = assertThrows(FrameException.class, () -> reader(bytes).read());

        assertEquals("frame of 4294967295 bytes exceeds the limit of 4194304 bytes", e.getMessage());
    }

    @Test
    void garbagePayloadIsUndecodable() {
        byte[] bytes = frame(5, "hello".getBytes(StandardCharsets.US_ASCII));

        FrameException e = assertThrows(FrameException.class, () -> reader(bytes).read());

        assertTrue(e.getMessage().startsWith("undecodable frame of 5 bytes"), e.getMessage());
    }

    @Test
    void unknownTypeInJsonIsNamed() {
        byte[] payload = "{\"type\":\"x\"}".getBytes(StandardCharsets.UTF_8);
        FrameReader reader = new FrameReader(new ByteArrayInputStream(frame(payload.length, payload)), JSON,
                FrameReader.DEFAULT_MAX_FRAME);

        FrameException e = assertThrows(FrameException.class, reader::read);

        assertEquals("unknown message type 'x'", e.getMessage());
    }

    @Test
    void unknownTypeInSmileIsNamed() throws IOException {
        byte[] payload = new SmileMapper().writeValueAsBytes(Map.of("type", "x"));

        FrameException e = assertThrows(FrameException.class, () -> reader(frame(payload.length, payload)).read());

        assertEquals("unknown message type 'x'", e.getMessage());
    }

    @ParameterizedTest
    @ValueSource(ints = {0, -1})
    void nonPositiveLimitIsRefused(int maxFrame) {
        InputStream in = new ByteArrayInputStream(new byte[0]);

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new FrameReader(in, SMILE, maxFrame));

        assertEquals(maxFrame + " was supplied for maxFrame: it must be greater than 0", e.getMessage());
    }
}
