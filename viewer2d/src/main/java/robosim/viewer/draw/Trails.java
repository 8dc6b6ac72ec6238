package robosim.viewer.draw;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;

/**
 * The path each robot has taken, from the snapshots seen so far: its true positions, a point kept
 * whenever it has moved {@value #SPACING_MM} mm from the last one kept. A robot that jumps (moved by
 * a control client's {@code move}, a Pioneer client's {@code SIM_SET_POSE}, or joining again where
 * it is placed) starts a new piece of path, so that no line is drawn across the jump: a jump is a
 * move between two snapshots faster than {@value #JUMP_SPEED_MM_S} mm/s of simulated time (faster
 * than any robot drives) and longer than {@value #SPACING_MM} mm, or a robot's joining again. A path
 * longer than {@value #MAX_POINTS} points keeps every other point of each piece (and each piece's
 * ends), so memory stays bounded however long the run. Plain data: fed by one thread, drawn by the
 * {@link WorldRenderer}.
 */
public final class Trails {
    /** How far a robot moves before its path gains a point, mm. */
    public static final double SPACING_MM = 20;
    /** The most points kept per robot. */
    public static final int MAX_POINTS = 20_000;
    /** A robot seen moving faster than this between two snapshots has jumped, mm/s of simulated time. */
    public static final double JUMP_SPEED_MM_S = 5000;

    private final Map<String, Path> paths = new LinkedHashMap<>();

    /** One robot's points, x0, y0, x1, y1, ..., and the indices of the points that start a piece. */
    private static final class Path {
        double[] xy = new double[64];
        int size;
        int[] starts = {0};
        int pieces = 1;
        double lastX = Double.NaN;
        double lastY = Double.NaN;
        long lastMs;

        void add(double x, double y, long timeMs, boolean rejoined) {
            boolean jumped = size > 0 && (rejoined || jump(x, y, timeMs));
            lastX = x;
            lastY = y;
            lastMs = timeMs;
            if (jumped) {
                if (starts[pieces - 1] == size / 2 - 1) {
                    // a piece of one point is no path: the jump replaces it
                    size -= 2;
                } else {
                    if (pieces == starts.length) {
                        starts = Arrays.copyOf(starts, pieces * 2);
                    }
                    starts[pieces++] = size / 2;
                }
            } else if (size > 0 && Math.hypot(x - xy[size - 2], y - xy[size - 1]) < SPACING_MM) {
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

        /** @return whether a move from the last position seen is a jump rather than driving */
        private boolean jump(double x, double y, long timeMs) {
            double apart = Math.hypot(x - lastX, y - lastY);
            double seconds = Math.max(0, timeMs - lastMs) / 1000.0;
            return apart > SPACING_MM && apart > JUMP_SPEED_MM_S * seconds;
        }

        /** Keeps every other point of each piece, and each piece's first and last. */
        private void thin() {
            int kept = 0;
            int[] newStarts = new int[starts.length];
            for (int p = 0; p < pieces; p++) {
                int from = starts[p];
                int to = p + 1 < pieces ? starts[p + 1] : size / 2;
                newStarts[p] = kept;
                for (int i = from; i < to; i++) {
                    if ((i - from) % 2 == 0 || i == to - 1) {
                        xy[2 * kept] = xy[2 * i];
                        xy[2 * kept + 1] = xy[2 * i + 1];
                        kept++;
                    }
                }
            }
            starts = newStarts;
            size = 2 * kept;
        }
    }

    /**
     * Extends each robot's path to its position in a snapshot; a robot with a non-finite position is
     * skipped. A robot that jumped, or joined again, starts a new piece.
     *
     * @param snapshot the next snapshot
     */
    public void add(Snapshot snapshot) {
        Set<String> rejoined = new HashSet<>();
        for (Snapshot.Event e : snapshot.events()) {
            if (!Departures.KINDS.contains(e.what())) {
                rejoined.add(e.robot());
            }
        }
        for (RobotView r : snapshot.robots()) {
            if (r.name() != null && Double.isFinite(r.x()) && Double.isFinite(r.y())) {
                paths.computeIfAbsent(r.name(), n -> new Path())
                        .add(r.x(), r.y(), snapshot.timeMs(), rejoined.contains(r.name()));
            }
        }
    }

    /** Forgets every path, as when a replay jumps back or a world is reloaded. */
    public void clear() {
        paths.clear();
    }

    /** Reads one piece of a robot's path without copying it. */
    @FunctionalInterface
    public interface PathVisitor {
        /**
         * @param robot the robot's name
         * @param xy    its path as x0, y0, x1, y1, ... in mm; read-only, valid during the call
         * @param from  the index of the piece's first point in {@code xy}
         * @param to    the index after the piece's last point
         */
        void visit(String robot, double[] xy, int from, int to);
    }

    /**
     * Visits every piece of every path, the robots in the order they first appeared and each
     * robot's pieces in order, without copying the points.
     *
     * @param visitor reads each piece
     */
    public void forEach(PathVisitor visitor) {
        for (Map.Entry<String, Path> e : paths.entrySet()) {
            Path p = e.getValue();
            for (int i = 0; i < p.pieces; i++) {
                int to = i + 1 < p.pieces ? p.starts[i + 1] : p.size / 2;
                visitor.visit(e.getKey(), p.xy, p.starts[i], to);
            }
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

    /**
     * @param robot a robot's name
     * @return how many pieces its path has: one more for each jump; 0 if it has none
     */
    public int pieces(String robot) {
        Path p = paths.get(robot);
        return p == null || p.size == 0 ? 0 : p.pieces;
    }
}
