package robosim.protocol.recording;

import java.io.ByteArrayOutputStream;
import java.util.zip.CRC32;
import java.util.zip.DataFormatException;
import java.util.zip.Deflater;
import java.util.zip.Inflater;

/**
 * Packs one message's Smile bytes into a record of the {@link RecordingFormat} and unpacks it:
 * DEFLATE with an optional dictionary, and the CRC-32. Holds its (de)compressor, so one codec
 * serves one writer or one reader.
 */
final class RecordCodec implements AutoCloseable {
    private final Deflater deflater = new Deflater(Deflater.BEST_COMPRESSION, true);
    private final Inflater inflater = new Inflater(true);
    private final byte[] buffer = new byte[1 << 14];

    /**
     * @param kind       the record's kind
     * @param message    the message's Smile bytes
     * @param dictionary the DEFLATE dictionary, or {@code null}
     * @return the whole record: kind, length, data, CRC
     */
    byte[] encode(byte kind, byte[] message, byte[] dictionary) {
        deflater.reset();
        if (dictionary != null) {
            deflater.setDictionary(dictionary);
        }
        deflater.setInput(message);
        deflater.finish();
        ByteArrayOutputStream record = new ByteArrayOutputStream(message.length / 2 + 64);
        record.write(new byte[5], 0, 5);
        while (!deflater.finished()) {
            int n = deflater.deflate(buffer);
            record.write(buffer, 0, n);
        }
        byte[] bytes = record.toByteArray();
        int length = bytes.length - 5;
        bytes[0] = kind;
        putInt(bytes, 1, length);
        CRC32 crc = new CRC32();
        crc.update(bytes, 0, bytes.length);
        byte[] whole = new byte[bytes.length + 4];
        System.arraycopy(bytes, 0, whole, 0, bytes.length);
        putInt(whole, bytes.length, (int) crc.getValue());
        return whole;
    }

    /**
     * @param kind   the record's kind byte
     * @param length its length field
     * @param data   its data
     * @return the CRC-32 the record must carry
     */
    static int crc(int kind, int length, byte[] data) {
        byte[] head = new byte[5];
        head[0] = (byte) kind;
        putInt(head, 1, length);
        CRC32 crc = new CRC32();
        crc.update(head);
        crc.update(data);
        return (int) crc.getValue();
    }

    /**
     * @param data       a record's data
     * @param dictionary the dictionary it was compressed with, or {@code null}
     * @return the message's Smile bytes
     * @throws DataFormatException if the data is not DEFLATE, needs another dictionary, does not
     *                             end, or inflates past {@link RecordingFormat#MAX_MESSAGE}
     */
    byte[] decode(byte[] data, byte[] dictionary) throws DataFormatException {
        inflater.reset();
        if (dictionary != null) {
            inflater.setDictionary(dictionary);
        }
        inflater.setInput(data);
        ByteArrayOutputStream out = new ByteArrayOutputStream(data.length * 3 + 64);
        while (!inflater.finished()) {
            int n = inflater.inflate(buffer);
            if (n == 0 && (inflater.needsInput() || inflater.needsDictionary())) {
                throw new DataFormatException("the compressed data ends before its last block");
            }
            out.write(buffer, 0, n);
            if (out.size() > RecordingFormat.MAX_MESSAGE) {
                throw new DataFormatException("it inflates past the limit of " + RecordingFormat.MAX_MESSAGE + " bytes");
            }
        }
        if (inflater.getRemaining() > 0) {
            throw new DataFormatException(inflater.getRemaining() + " bytes follow the end of the compressed data");
        }
        return out.toByteArray();
    }

    static void putInt(byte[] b, int at, int v) {
        b[at] = (byte) (v >>> 24);
        b[at + 1] = (byte) (v >>> 16);
        b[at + 2] = (byte) (v >>> 8);
        b[at + 3] = (byte) v;
    }

    @Override
    public void close() {
        deflater.end();
        inflater.end();
    }
}
