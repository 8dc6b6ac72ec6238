package robosim.aria;

import robosim.map.MapHeader;

/**
 * ARIA's bounds of a scan ({@code ArMapScan::loadDataPoint}, {@code handleMinPos},
 * {@code handleNumPoints}): they start from the header's corners, or (0, 0), or the empty
 * extremes when the header declares no items, and each item read widens them.
 */
final class MapBounds {
    private double minX;
    private double minY;
    private double maxX;
    private double maxY;

    MapBounds(long declared, MapHeader.Position min, MapHeader.Position max) {
        if (declared == 0) {
            minX = Integer.MAX_VALUE;
            minY = Integer.MAX_VALUE;
            maxX = Integer.MIN_VALUE;
            maxY = Integer.MIN_VALUE;
            return;
        }
        if (min != null) {
            minX = min.x();
            minY = min.y();
        }
        if (max != null) {
            maxX = max.x();
            maxY = max.y();
        }
    }

    void add(double x, double y) {
        maxX = Math.max(maxX, x);
        maxY = Math.max(maxY, y);
        minX = Math.min(minX, x);
        minY = Math.min(minY, y);
    }

    ArPose min() {
        return new ArPose(minX, minY);
    }

    ArPose max() {
        return new ArPose(maxX, maxY);
    }
}
