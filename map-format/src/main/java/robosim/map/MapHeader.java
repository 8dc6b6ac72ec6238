package robosim.map;

import java.util.List;

/**
 * What a map's header says besides its cairns and resolution: the counts it declares, the corners
 * it gives for its points and its lines, and its {@code MapInfo:} lines. ARIA's {@code ArMapScan}
 * (ArMapComponents.cpp: {@code handleNumPoints}, {@code handleMinPos}, {@code handleLineMinPos}, ...)
 * starts its bounds from these before it reads the points and lines.
 *
 * @param numPoints  the {@code NumPoints:} value, or -1 when the header has none
 * @param numLines   the {@code NumLines:} value, or -1 when the header has none
 * @param minPos     the {@code MinPos:} corner, or null when the header has none
 * @param maxPos     the {@code MaxPos:} corner, or null when the header has none
 * @param lineMinPos the {@code LineMinPos:} corner, or null when the header has none
 * @param lineMaxPos the {@code LineMaxPos:} corner, or null when the header has none
 * @param mapInfo    the values of the {@code MapInfo:} lines, in file order, stripped
 */
public record MapHeader(long numPoints, long numLines, Position minPos, Position maxPos, Position lineMinPos,
                        Position lineMaxPos, List<String> mapInfo) {
    /** A header that says nothing: no counts, no corners, no map info. */
    public static final MapHeader EMPTY = new MapHeader(-1, -1, null, null, null, null, List.of());

    /** Copies the list so the record stays immutable. */
    public MapHeader {
        mapInfo = List.copyOf(mapInfo);
    }

    /**
     * A corner the header gives.
     *
     * @param x mm
     * @param y mm
     */
    public record Position(double x, double y) {
    }
}
