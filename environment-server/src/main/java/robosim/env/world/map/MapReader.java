package robosim.env.world.map;

import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.logging.Logger;

/**
 * Reads an ARIA map file ({@code 2D-Map}, and the {@code 2D-Map-Ex} forms ARIA writes): the
 * header's {@code Resolution}, {@code NumPoints}, {@code NumLines} and {@code Cairn} lines (other
 * header keys are skipped), then {@code LINES} sections of {@code x1 y1 x2 y2} lines and
 * {@code DATA} sections of {@code x y} points, in either order ({@code SENSOR_LINES} and
 * {@code SENSOR_DATA} sections of the {@code -Ex} forms count as such). The first broken rule stops
 * reading with a {@link MapFileException} naming the file, the line and the rule; counts that
 * disagree with the header are only logged.
 */
public final class MapReader {
    /** The most points, and the most lines, one map may hold: bounds the memory a file can ask for. */
    public static final int MAX_ITEMS = 10_000_000;
    /** The largest number a map may hold either way, as in a world file (1000 km in mm). */
    static final double MAX_MAGNITUDE = 1e9;

    private static final Logger LOG = Logger.getLogger(MapReader.class.getName());

    private enum Section { HEADER, LINES, POINTS }

    private final Path file;
    private double resolution;
    private long declaredPoints = -1;
    private long declaredLines = -1;
    private final Coordinates lines = new Coordinates(4);
    private final Coordinates points = new Coordinates(2);
    private final List<Cairn> cairns = new ArrayList<>();

    private MapReader(Path file) {
        this.file = file;
    }

    /**
     * Reads and checks a map file.
     *
     * @param file the map file
     * @return what it holds
     * @throws MapFileException if the file cannot be read or breaks a rule of the format
     */
    public static MapFile read(Path file) {
        MapReader reader = new MapReader(file);
        // ISO-8859-1 maps every byte to a character: a stray byte in a label cannot stop reading
        try (BufferedReader in = Files.newBufferedReader(file, StandardCharsets.ISO_8859_1)) {
            reader.readAll(in);
        } catch (NoSuchFileException e) {
            throw new MapFileException(file, 0, "no such map file");
        } catch (IOException e) {
            throw new MapFileException(file, 0, "cannot read the map file: " + e);
        }
        return reader.result();
    }

    private void readAll(BufferedReader in) throws IOException {
        String first = in.readLine();
        if (first == null || !first.strip().matches("2D-Map(-Ex\\d*)?")) {
            throw new MapFileException(file, 1, "the first line is '" + shorten(first == null ? "" : first.strip())
                    + "' but a map file starts with 2D-Map (or 2D-Map-Ex, 2D-Map-Ex2, ...)");
        }
        Section section = Section.HEADER;
        int lineNo = 1;
        for (String text = in.readLine(); text != null; text = in.readLine()) {
            lineNo++;
            String line = text.strip();
            if (line.isEmpty()) {
                continue;
            }
            if (line.equals("LINES") || line.endsWith("_LINES") && line.indexOf(' ') < 0) {
                section = Section.LINES;
            } else if (line.equals("DATA") || line.endsWith("_DATA") && line.indexOf(' ') < 0) {
                section = Section.POINTS;
            } else if (section == Section.HEADER) {
                header(line, lineNo);
            } else if (section == Section.LINES) {
                data(lines, line, lineNo, "a line of LINES holds x1 y1 x2 y2");
            } else {
                data(points, line, lineNo, "a point of DATA holds x y");
            }
        }
    }

    private void header(String line, int lineNo) {
        int colon = line.indexOf(':');
        if (colon < 0) {
            throw new MapFileException(file, lineNo, "'" + shorten(line) + "' is neither a 'Key: values' header"
                    + " line nor LINES or DATA");
        }
        String key = line.substring(0, colon).strip();
        String value = line.substring(colon + 1).strip();
        switch (key) {
            case "Resolution" -> resolution = wholeOrDecimal(value, lineNo, "Resolution", 0, MAX_MAGNITUDE);
            case "NumPoints" -> declaredPoints = (long) wholeOrDecimal(value, lineNo, "NumPoints", 0, MAX_MAGNITUDE);
            case "NumLines" -> declaredLines = (long) wholeOrDecimal(value, lineNo, "NumLines", 0, MAX_MAGNITUDE);
            case "Cairn" -> cairns.add(CairnParser.parse(file, lineNo, value));
            default -> { } // MinPos, MapInfo, custom keys: nothing a simulated world needs
        }
    }

    private double wholeOrDecimal(String value, int lineNo, String key, double min, double max) {
        double v = Numbers.parse(file, lineNo, value, key);
        if (v < min || v > max) {
            throw new MapFileException(file, lineNo, key + " is " + value + " but must be from " + (long) min
                    + " to " + (long) max);
        }
        return v;
    }

    private void data(Coordinates into, String line, int lineNo, String rule) {
        String[] tokens = tokens(line, into.width);
        if (tokens == null) {
            int count = line.split("\\s+").length;
            throw new MapFileException(file, lineNo, "'" + shorten(line) + "' has " + count + " value"
                    + (count == 1 ? "" : "s") + " but " + rule);
        }
        if (into.count() >= MAX_ITEMS) {
            throw new MapFileException(file, lineNo, "a map holds at most " + MAX_ITEMS + " lines and "
                    + MAX_ITEMS + " points");
        }
        for (String token : tokens) {
            into.add(Numbers.coordinate(file, lineNo, token, "coordinate"));
        }
        into.lineNumber(lineNo);
    }

    /** @return the line's {@code count} white-space separated tokens, or null if it has another number of them */
    private static String[] tokens(String line, int count) {
        String[] out = new String[count];
        int n = 0;
        int i = 0;
        int len = line.length();
        while (i < len) {
            while (i < len && Character.isWhitespace(line.charAt(i))) {
                i++;
            }
            if (i == len) {
                break;
            }
            int start = i;
            while (i < len && !Character.isWhitespace(line.charAt(i))) {
                i++;
            }
            if (n == count) {
                return null;
            }
            out[n++] = line.substring(start, i);
        }
        return n == count ? out : null;
    }

    private MapFile result() {
        warnIfDiffers("NumLines", declaredLines, lines.count());
        warnIfDiffers("NumPoints", declaredPoints, points.count());
        return new MapFile(file, resolution, lines.values(), lines.lineNumbers(), points.values(),
                points.lineNumbers(), cairns);
    }

    private void warnIfDiffers(String key, long declared, int found) {
        if (declared >= 0 && declared != found) {
            LOG.warning(() -> file + ": the header says " + key + ": " + declared + " but the map holds " + found);
        }
    }

    static String shorten(String text) {
        return text.length() <= 60 ? text : text.substring(0, 57) + "...";
    }

    /** Coordinates growing in place: a list of boxed doubles would take five times the memory. */
    private static final class Coordinates {
        final int width;
        private double[] values = new double[1024];
        private int[] lineNumbers = new int[256];
        private int size;
        private int items;

        Coordinates(int width) {
            this.width = width;
        }

        void add(double v) {
            if (size == values.length) {
                values = Arrays.copyOf(values, size * 2);
            }
            values[size++] = v;
        }

        void lineNumber(int line) {
            if (items == lineNumbers.length) {
                lineNumbers = Arrays.copyOf(lineNumbers, items * 2);
            }
            lineNumbers[items++] = line;
        }

        int count() {
            return items;
        }

        double[] values() {
            return Arrays.copyOf(values, size);
        }

        int[] lineNumbers() {
            return Arrays.copyOf(lineNumbers, items);
        }
    }
}
