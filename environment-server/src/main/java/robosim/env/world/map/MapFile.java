package robosim.env.world.map;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;

/**
 * What a map file holds, as read, with the line each item came from.
 *
 * @param source     the file
 * @param resolution the map's {@code Resolution} header, mm, or 0 when it has none
 * @param lines      the {@code LINES} section: x1, y1, x2, y2 for each line, mm
 * @param lineLines  the file line of each of {@code lines}' lines
 * @param points     the {@code DATA} section: x, y for each point, mm
 * @param pointLines the file line of each point
 * @param cairns     the cairns, in file order
 */
public record MapFile(Path source, double resolution, double[] lines, int[] lineLines, double[] points,
                      int[] pointLines, List<Cairn> cairns) {

    /** Copies the arrays and the list so the record stays immutable. */
    public MapFile {
        lines = lines.clone();
        lineLines = lineLines.clone();
        points = points.clone();
        pointLines = pointLines.clone();
        cairns = List.copyOf(cairns);
    }

    /** @return a copy of the lines' coordinates */
    @Override
    public double[] lines() {
        return lines.clone();
    }

    /** @return a copy of the lines' file lines */
    @Override
    public int[] lineLines() {
        return lineLines.clone();
    }

    /** @return a copy of the points' coordinates */
    @Override
    public double[] points() {
        return points.clone();
    }

    /** @return a copy of the points' file lines */
    @Override
    public int[] pointLines() {
        return pointLines.clone();
    }

    /** Compares the contents of the arrays, not their identity. */
    @Override
    public boolean equals(Object o) {
        return o instanceof MapFile m && source.equals(m.source) && resolution == m.resolution
                && Arrays.equals(lines, m.lines) && Arrays.equals(lineLines, m.lineLines)
                && Arrays.equals(points, m.points) && Arrays.equals(pointLines, m.pointLines)
                && cairns.equals(m.cairns);
    }

    @Override
    public int hashCode() {
        return Objects.hash(source, resolution, Arrays.hashCode(lines), Arrays.hashCode(points), cairns);
    }

    @Override
    public String toString() {
        return "MapFile[" + source + ", " + lineLines.length + " lines, " + pointLines.length + " points, "
                + cairns.size() + " cairns]";
    }

    /** @return the number of lines */
    public int lineCount() {
        return lineLines.length;
    }

    /** @return the number of points */
    public int pointCount() {
        return pointLines.length;
    }
}
