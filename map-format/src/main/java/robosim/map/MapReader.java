package robosim.map;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.logging.Logger;

/**
 * Reads an ARIA map file ({@code 2D-Map}, and the {@code 2D-Map-Ex} forms ARIA writes): the
 * header's {@code Resolution}, {@code NumPoints}, {@code NumLines}, {@code MinPos}, {@code MaxPos},
 * {@code LineMinPos}, {@code LineMaxPos}, {@code MapInfo} and {@code Cairn} lines (other header keys
 * are skipped), then {@code LINES} sections of {@code x1 y1 x2 y2} lines and
 * {@code DATA} sections of {@code x y} points, in either order ({@code SENSOR_LINES} and
 * {@code SENSOR_DATA} sections of the {@code -Ex} forms count as such). The first broken rule stops
 * reading with a {@link MapFileException} naming the file, the line and the rule, quoting at most
 * {@value MapLines#EXCERPT} characters of what the file says, escaped; counts that disagree with
 * the header are only logged, once each.
 *
 * <p>Hostile files are bounded: a line longer than {@value MapLines#MAX_LENGTH} characters is
 * refused before it is held whole, the items are kept on primitive arrays as they are parsed
 * ({@link Coordinates}), at most {@value #MAX_ITEMS} of each kind, and a map whose items would
 * not fit this JVM's heap is refused before they are read ({@link MapMemory}).
 */
public final class MapReader {
    /** The most points, and the most lines, one map may hold: bounds the memory a file can ask for. */
    public static final int MAX_ITEMS = 10_000_000;
    /** The largest number a map may hold either way, as in a world file (1000 km in mm). */
    static final double MAX_MAGNITUDE = 1e9;
    /** The largest coordinate a map may hold either way, mm (100 km), as a world file's size. */
    public static final double MAX_COORDINATE = 100_000_000;
    /** The header keys of the corners, in the order {@link MapHeader} holds them. */
    private static final List<String> CORNER_KEYS = List.of("MinPos", "MaxPos", "LineMinPos", "LineMaxPos");

    private static final Logger LOG = Logger.getLogger(MapReader.class.getName());

    private enum Section { HEADER, LINES, POINTS }

    private final Path file;
    private final MapMemory memory;
    private double resolution;
    private long declaredPoints = -1;
    private long declaredLines = -1;
    private int countsLine;
    private final Coordinates lines = new Coordinates(4);
    private final Coordinates points = new Coordinates(2);
    private final List<Cairn> cairns = new ArrayList<>();
    private final List<String> mapInfo = new ArrayList<>();
    private final MapHeader.Position[] corners = new MapHeader.Position[4];
    private final double[] item = new double[4];

    private MapReader(Path file, long maxHeap) {
        this.file = file;
        this.memory = new MapMemory(file, maxHeap);
    }

    /**
     * Reads and checks a map file.
     *
     * @param file the map file
     * @return what it holds
     * @throws MapFileException if the file cannot be read, breaks a rule of the format, or holds
     *                          more than this JVM's heap can take (the message names -Xmx)
     */
    public static MapFile read(Path file) {
        return read(file, Runtime.getRuntime().maxMemory());
    }

    /**
     * Reads and checks a map file as {@link #read(Path)} does, for a JVM of the given heap.
     *
     * @param file    the map file
     * @param maxHeap the most heap the map may take, bytes
     * @return what it holds
     */
    static MapFile read(Path file, long maxHeap) {
        MapReader reader = new MapReader(file, maxHeap);
        try (InputStream in = Files.newInputStream(file)) {
            reader.readAll(new MapLines(file, in));
        } catch (NoSuchFileException e) {
            throw new MapFileException(file, 0, "no such map file");
        } catch (IOException e) {
            throw new MapFileException(file, 0, "cannot read the map file: " + MapLines.excerpt(e.toString()));
        }
        return reader.result();
    }

    private void readAll(MapLines in) throws IOException {
        if (!in.next() || !in.text().matches("2D-Map(-Ex\\d*)?")) {
            throw new MapFileException(file, 1, "the first line is '" + in.excerpt() + "' but a map file starts"
                    + " with 2D-Map (or 2D-Map-Ex, 2D-Map-Ex2, ...)");
        }
        Section section = Section.HEADER;
        while (in.next()) {
            char[] c = in.chars();
            int from = skipSpace(c, 0, in.length());
            int to = in.length();
            while (to > from && Character.isWhitespace(c[to - 1])) {
                to--;
            }
            if (from == to) {
                continue;
            }
            if (section != Section.HEADER && isNumberLine(c, from, to)) {
                item(section == Section.LINES ? lines : points, in, from, to);
                continue;
            }
            String line = new String(c, from, to - from);
            Section next = line.equals("LINES") || line.endsWith("_LINES") && line.indexOf(' ') < 0 ? Section.LINES
                    : line.equals("DATA") || line.endsWith("_DATA") && line.indexOf(' ') < 0 ? Section.POINTS
                    : null;
            if (next != null) {
                if (section == Section.HEADER) {
                    memory.check(Math.max(0, declaredPoints), Math.max(0, declaredLines), countsLine,
                            "the header says the map holds");
                }
                section = next;
            } else if (section == Section.HEADER) {
                header(line, in.number());
            } else {
                item(section == Section.LINES ? lines : points, in, from, to);
            }
        }
    }

    /** @return whether the line is read as numbers at once: it cannot be a section's name, which ends in S or A */
    private static boolean isNumberLine(char[] c, int from, int to) {
        char last = c[to - 1];
        return last != 'S' && last != 'A';
    }

    private void header(String line, int lineNo) {
        int colon = line.indexOf(':');
        if (colon < 0) {
            throw new MapFileException(file, lineNo, "'" + MapLines.excerpt(line) + "' is neither a 'Key: values'"
                    + " header line nor LINES or DATA");
        }
        String key = line.substring(0, colon).strip();
        String value = line.substring(colon + 1).strip();
        switch (key) {
            case "Resolution" -> resolution = wholeOrDecimal(value, lineNo, "Resolution");
            case "NumPoints" -> declaredPoints = count(value, lineNo, "NumPoints");
            case "NumLines" -> declaredLines = count(value, lineNo, "NumLines");
            case "Cairn" -> cairns.add(CairnParser.parse(file, lineNo, value));
            case "MinPos", "MaxPos", "LineMinPos", "LineMaxPos" -> corners[CORNER_KEYS.indexOf(key)] =
                    corner(value, lineNo, key);
            case "MapInfo" -> mapInfo.add(value);
            default -> { } // custom keys: nothing a map reader needs
        }
    }

    private MapHeader.Position corner(String value, int lineNo, String key) {
        String[] xy = value.isEmpty() ? new String[0] : value.split("\\s+");
        if (xy.length != 2) {
            throw new MapFileException(file, lineNo, key + " has " + xy.length + " value" + (xy.length == 1 ? "" : "s")
                    + " but holds x y");
        }
        return new MapHeader.Position(Numbers.coordinate(file, lineNo, xy[0], key + " x"),
                Numbers.coordinate(file, lineNo, xy[1], key + " y"));
    }

    private long count(String value, int lineNo, String key) {
        countsLine = lineNo;
        return (long) wholeOrDecimal(value, lineNo, key);
    }

    private double wholeOrDecimal(String value, int lineNo, String key) {
        double v = Numbers.parse(file, lineNo, value, key);
        if (v < 0 || v > MAX_MAGNITUDE) {
            throw new MapFileException(file, lineNo, key + " is " + MapLines.excerpt(value) + " but must be from 0"
                    + " to " + (long) MAX_MAGNITUDE);
        }
        return v;
    }

    /** Reads the numbers of a line of LINES or a point of DATA from {@code from} to {@code to} of the line. */
    private void item(Coordinates into, MapLines in, int from, int to) {
        char[] c = in.chars();
        int width = into == lines ? 4 : 2;
        int count = countTokens(c, from, to);
        if (count != width) {
            throw new MapFileException(file, in.number(), "'" + in.excerpt() + "' has " + count + " value"
                    + (count == 1 ? "" : "s") + " but " + (width == 4 ? "a line of LINES holds x1 y1 x2 y2"
                    : "a point of DATA holds x y"));
        }
        if (into.count() >= MAX_ITEMS) {
            throw new MapFileException(file, in.number(), "a map holds at most " + MAX_ITEMS + " lines and "
                    + MAX_ITEMS + " points");
        }
        int i = from;
        for (int k = 0; k < width; k++) {
            int start = skipSpace(c, i, to);
            i = start;
            while (i < to && !Character.isWhitespace(c[i])) {
                i++;
            }
            item[k] = Numbers.coordinate(file, in.number(), c, start, i, "coordinate");
        }
        into.add(item, 0, in.number());
        if (((points.count() + lines.count()) & (MapMemory.CHECK_EVERY - 1)) == 0) {
            memory.check(points.count(), lines.count(), in.number(), "the map holds at least");
        }
    }

    private static int skipSpace(char[] c, int from, int to) {
        int i = from;
        while (i < to && Character.isWhitespace(c[i])) {
            i++;
        }
        return i;
    }

    private static int countTokens(char[] c, int from, int to) {
        int n = 0;
        for (int i = from; i < to; i++) {
            if (!Character.isWhitespace(c[i]) && (i == from || Character.isWhitespace(c[i - 1]))) {
                n++;
            }
        }
        return n;
    }

    private MapFile result() {
        memory.check(points.count(), lines.count(), 0, "the map holds");
        warnIfDiffers("NumLines", declaredLines, lines.count());
        warnIfDiffers("NumPoints", declaredPoints, points.count());
        MapHeader header = new MapHeader(declaredPoints, declaredLines, corners[0], corners[1], corners[2], corners[3],
                mapInfo);
        return new MapFile(file, resolution, lines, points, cairns, header);
    }

    private void warnIfDiffers(String key, long declared, int found) {
        if (declared >= 0 && declared != found) {
            LOG.warning(() -> file + ": the header says " + key + ": " + declared + " but the map holds " + found);
        }
    }
}
