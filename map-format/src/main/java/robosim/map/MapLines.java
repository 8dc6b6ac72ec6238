package robosim.map;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Path;
import robosim.protocol.RobotHello;

/**
 * Reads a map file line by line into one reusable buffer of at most {@value #MAX_LENGTH}
 * characters, each byte one ISO-8859-1 character (so a stray byte in a label cannot stop reading).
 * A line ends at {@code \n}, {@code \r} or {@code \r\n}, as {@link java.io.BufferedReader#readLine()}
 * counts them, so line numbers are the same as a text editor's. A longer line is refused before
 * it is held whole: a 100 MB line costs a buffer of {@value #MAX_LENGTH} characters, not 100 MB.
 */
final class MapLines {
    /** The longest line read, in characters: a map's longest lines, its cairns, are well under 1 KB. */
    static final int MAX_LENGTH = 16 * 1024;
    /** The characters of a line that an error message quotes, escaped. */
    static final int EXCERPT = 60;

    private final Path file;
    private final InputStream in;
    private final byte[] block = new byte[64 * 1024];
    private int blockSize;
    private int blockPos;
    private final char[] line = new char[MAX_LENGTH];
    private int length;
    private int number;
    private boolean afterCarriageReturn;

    /**
     * @param file the map file, for messages
     * @param in   its bytes
     */
    MapLines(Path file, InputStream in) {
        this.file = file;
        this.in = in;
    }

    /**
     * Reads the next line.
     *
     * @return whether there was one
     * @throws MapFileException if it is longer than {@value #MAX_LENGTH} characters
     * @throws IOException      if the file cannot be read
     */
    boolean next() throws IOException {
        length = 0;
        boolean any = false;
        while (true) {
            if (blockPos == blockSize && !fill()) {
                if (any) {
                    number++;
                }
                return any;
            }
            byte b = block[blockPos++];
            if (b == '\n' && afterCarriageReturn && !any) {
                afterCarriageReturn = false;
                continue; // the \n of a \r\n
            }
            afterCarriageReturn = b == '\r';
            if (b == '\n' || b == '\r') {
                number++;
                return true;
            }
            any = true;
            if (length == MAX_LENGTH) {
                throw new MapFileException(file, number + 1, "the line is longer than " + MAX_LENGTH
                        + " characters, more than any map line needs; it starts '" + excerpt() + "'");
            }
            line[length++] = (char) (b & 0xff);
        }
    }

    private boolean fill() throws IOException {
        blockSize = in.read(block);
        blockPos = 0;
        if (blockSize < 0) {
            blockSize = 0;
            return false;
        }
        return true;
    }

    /** @return the characters of the line, valid up to {@link #length()} until the next {@link #next()} */
    char[] chars() {
        return line;
    }

    /** @return the line's length */
    int length() {
        return length;
    }

    /** @return the 1-based number of the line last read */
    int number() {
        return number;
    }

    /** @return the line as a string, its white space at both ends stripped */
    String text() {
        return new String(line, 0, length).strip();
    }

    /** @return the start of the line, stripped, as an error message may quote it: short and escaped */
    String excerpt() {
        return excerpt(new String(line, 0, Math.min(length, 4 * EXCERPT)).strip());
    }

    /**
     * @param text any text from a map file
     * @return its first {@value #EXCERPT} characters, anything outside printable ASCII escaped
     */
    static String excerpt(String text) {
        return RobotHello.printable(text, EXCERPT);
    }
}
