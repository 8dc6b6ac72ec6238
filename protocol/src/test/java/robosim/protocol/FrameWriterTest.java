package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.MessageCodec.Format;

class FrameWriterTest {

    @Test
    void writesABigEndianLengthThenThePayload() throws IOException {
        MessageCodec codec = new MessageCodec(Format.JSON);
        ByteArrayOutputStream out = new ByteArrayOutputStream();

        new FrameWriter(out, codec).write(new Bye("done"));

        byte[] payload = "{\"type\":\"bye\",\"reason\":\"done\"}".getBytes(StandardCharsets.UTF_8);
        byte[] expected = new byte[4 + payload.length];
        expected[3] = (byte) payload.length;
        System.arraycopy(payload, 0, expected, 4, payload.length);
        assertArrayEquals(expected, out.toByteArray());
    }

    @Test
    void lengthOverOneByteIsWrittenInFull() throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        MessageCodec codec = new MessageCodec();
        byte[] payload = codec.encode(Messages.worldDescription());

        new FrameWriter(out, codec).write(Messages.worldDescription());

        byte[] bytes = out.toByteArray();
        assertEquals(payload.length, ByteBuffer.wrap(bytes, 0, 4).getInt());
        assertArrayEquals(payload, Arrays.copyOfRange(bytes, 4, bytes.length));
    }

    @Test
    void flushesEachMessage() throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        FrameWriter writer = new FrameWriter(out, new MessageCodec());

        writer.write(Messages.bye());
        int afterFirst = out.size();
        writer.write(Messages.bye());

        assertEquals(4 + new MessageCodec().encode(Messages.bye()).length, afterFirst);
        assertEquals(2 * afterFirst, out.size());
    }

    @Test
    void framesFromConcurrentWritersDoNotInterleave() throws Exception {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        MessageCodec codec = new MessageCodec();
        FrameWriter writer = new FrameWriter(out, codec);
        List<Thread> threads = new ArrayList<>();
        for (int t = 0; t < 4; t++) {
            Thread thread = new Thread(() -> {
                try {
                    for (int i = 0; i < 200; i++) {
                        writer.write(Messages.timeStep());
                    }
                } catch (IOException e) {
                    throw new AssertionError(e);
                }
            });
            threads.add(thread);
            thread.start();
        }
        for (Thread thread : threads) {
            thread.join();
        }

        FrameReader reader = new FrameReader(new ByteArrayInputStream(out.toByteArray()), codec,
                FrameReader.DEFAULT_MAX_FRAME);
        for (int i = 0; i < 800; i++) {
            RecordAssert.assertDeepEquals(Messages.timeStep(), reader.read());
        }
        assertNull(reader.read());
    }
}
