package robosim.env.world.map;

import java.nio.file.Path;
import java.util.List;

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

    /** @return the number of lines */
    public int lineCount() {
        return lineLines.length;
    }

    /** @return the number of points */
    public int pointCount() {
        return pointLines.length;
    }
}
