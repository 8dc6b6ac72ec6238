package robosim.map;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;

/**
 * What a map file holds, as read, with the line each item came from. The lines and points are
 * kept as read ({@link Coordinates}, 8 bytes a number); the accessors that return arrays make
 * them afresh on each call, for tests and tools; {@link #lineItems()} and {@link #pointItems()}
 * give them in place, for a large map's geometry.
 */
public final class MapFile {
    private final Path source;
    private final double resolution;
    private final Coordinates lines;
    private final Coordinates points;
    private final List<Cairn> cairns;
    private final MapHeader header;

    /**
     * @param source     the file
     * @param resolution the map's {@code Resolution} header, mm, or 0 when it has none
     * @param lines      the {@code LINES} section: x1, y1, x2, y2 for each line, mm
     * @param lineLines  the file line of each of {@code lines}' lines
     * @param points     the {@code DATA} section: x, y for each point, mm
     * @param pointLines the file line of each point
     * @param cairns     the cairns, in file order
     */
    public MapFile(Path source, double resolution, double[] lines, int[] lineLines, double[] points,
                   int[] pointLines, List<Cairn> cairns) {
        this(source, resolution, Coordinates.of(4, lines, lineLines), Coordinates.of(2, points, pointLines), cairns,
                MapHeader.EMPTY);
    }

    MapFile(Path source, double resolution, Coordinates lines, Coordinates points, List<Cairn> cairns,
            MapHeader header) {
        this.source = source;
        this.resolution = resolution;
        this.lines = lines;
        this.points = points;
        this.cairns = List.copyOf(cairns);
        this.header = header;
    }

    /** @return the file */
    public Path source() {
        return source;
    }

    /** @return the map's {@code Resolution} header, mm, or 0 when it has none */
    public double resolution() {
        return resolution;
    }

    /** @return the lines' coordinates, x1, y1, x2, y2 each, in a new array */
    public double[] lines() {
        return lines.values();
    }

    /** @return the lines' file lines, in a new array */
    public int[] lineLines() {
        return lines.lineNumbers();
    }

    /** @return the points' coordinates, x, y each, in a new array */
    public double[] points() {
        return points.values();
    }

    /** @return the points' file lines, in a new array */
    public int[] pointLines() {
        return points.lineNumbers();
    }

    /** @return the cairns, in file order */
    public List<Cairn> cairns() {
        return cairns;
    }

    /** @return the rest of the header: declared counts, corners, map info */
    public MapHeader header() {
        return header;
    }

    /** @return the lines as read, in place: not to be changed */
    public Coordinates lineItems() {
        return lines;
    }

    /** @return the points as read, in place: not to be changed */
    public Coordinates pointItems() {
        return points;
    }

    /** Compares the contents, not the arrays' identity. */
    @Override
    public boolean equals(Object o) {
        return o instanceof MapFile m && source.equals(m.source) && resolution == m.resolution
                && Arrays.equals(lines(), m.lines()) && Arrays.equals(lineLines(), m.lineLines())
                && Arrays.equals(points(), m.points()) && Arrays.equals(pointLines(), m.pointLines())
                && cairns.equals(m.cairns);
    }

    @Override
    public int hashCode() {
        return Objects.hash(source, resolution, Arrays.hashCode(lines()), Arrays.hashCode(points()), cairns);
    }

    @Override
    public String toString() {
        return "MapFile[" + source + ", " + lines.count() + " lines, " + points.count() + " points, "
                + cairns.size() + " cairns]";
    }

    /** @return the number of lines */
    public int lineCount() {
        return lines.count();
    }

    /** @return the number of points */
    public int pointCount() {
        return points.count();
    }
}
