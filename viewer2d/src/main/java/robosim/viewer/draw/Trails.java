package robosim.viewer.draw;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;

/**
 * The path each robot has taken, from the snapshots seen so far: its true positions, a point kept
 * whenever it has moved {@value #SPACING_MM} mm from the last one kept. A path longer than
 * {@value #MAX_POINTS} points keeps every other point, so memory stays bounded however long the
 * run. Plain data: fed by one thread, drawn by the {@link WorldRenderer}.
 */
public final class Trails {
    /** How far a robot moves before its path gains a point, mm. */
    public static final double SPACING_MM = 20;
    /** The most points kept per robot. */
    public static final int MAX_POINTS = 20_000;

    private final Map<String, Path> paths = new LinkedHashMap<>();

    /** One robot's points, x0, y0, x1, y1, ... */
    private static final class Path {
        double[] xy = new double[64];
        int size;

        void add(double x, double y) {
            if (size > 0 && Math.hypot(x - xy[size - 2], y - xy[size - 1]) < SPACING_MM) {
                return;
            }
            if (size / 2 >= MAX_POINTS) {
                thin();
            }
            if (size + 2 > xy.length) {
                xy = Arrays.copyOf(xy, xy.length * 2);
            }
            xy[size++] = x;
            xy[size++] = y;
        }

        /** Keeps every other point, and the latest. */
        private void thin() {
            int kept = 0;
            for (int i = 0; i < size; i += 4) {
                xy[kept++] = xy[i];
                xy[kept++] = xy[i + 1];
            }
            size = kept;
        }
    }

    /**
     * Extends each robot's path to its position in a snapshot; a robot with a non-finite position is
     * skipped.
     *
     * @param snapshot the next snapshot
     */
    public void add(Snapshot snapshot) {
        for (RobotView r : snapshot.robots()) {
            if (r.name() != null && Double.isFinite(r.x()) && Double.isFinite(r.y())) {
                paths.computeIfAbsent(r.name(), n -> new Path()).add(r.x(), r.y());
            }
        }
    }

    /** Forgets every path, as when a replay jumps back or a world is reloaded. */
    public void clear() {
        paths.clear();
    }

    /** Reads one robot's path without copying it. */
    @FunctionalInterface
    public interface PathVisitor {
        /**
         * @param robot the robot's name
         * @param xy    its path as x0, y0, x1, y1, ... in mm; read-only, valid during the call
         * @param size  how many points of {@code xy} are in use
         */
        void visit(String robot, double[] xy, int size);
    }

    /**
     * Visits every path in the order the robots first appeared, without copying the points.
     *
     * @param visitor reads each path
     */
    public void forEach(PathVisitor visitor) {
        for (Map.Entry<String, Path> e : paths.entrySet()) {
            visitor.visit(e.getKey(), e.getValue().xy, e.getValue().size / 2);
        }
    }

    /** @return the robots that have a path, in the order they first appeared */
    public List<String> robots() {
        return new ArrayList<>(paths.keySet());
    }

    /**
     * @param robot a robot's name
     * @return its path as x0, y0, x1, y1, ... in mm; empty if it has none
     */
    public double[] points(String robot) {
        Path p = paths.get(robot);
        return p == null ? new double[0] : Arrays.copyOf(p.xy, p.size);
    }
}
