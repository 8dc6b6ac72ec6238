package robosim.examples.aria;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.PriorityQueue;
import robosim.aria.ArLineSegment;
import robosim.aria.ArMap;
import robosim.aria.ArMapObject;
import robosim.aria.ArPose;

/**
 * A route on a map's grid: the map's lines and points (its walls and what a laser saw) and its
 * forbidden lines and areas are drawn into cells, grown by {@code clearance}, and the shortest way
 * between free cells (A*, eight neighbours) is cut to the fewest straight legs that stay clear.
 * Cells within {@code clearance} of something are passable at a high cost, so a robot that starts or
 * ends near a wall still finds its way out; the lines and points themselves never are. Small on
 * purpose: an example of planning on {@link ArMap}, not ARIA's path planner.
 */
final class MapRoute {
    /** The grid's cell, mm; larger for a map that would need more than {@link #MAX_CELLS}. */
    private static final double CELL = 100;
    private static final int MAX_CELLS = 4_000_000;
    /** The cost of a cell within the clearance, against 1 for a free one. */
    private static final double NEAR_COST = 50;
    private static final byte FREE = 0;
    private static final byte NEAR = 1;
    private static final byte BLOCKED = 2;

    private final List<ArLineSegment> forbidden = new ArrayList<>();
    private final double cell;
    private final double minX;
    private final double minY;
    private final int width;
    private final int height;
    private final byte[] grid;

    /**
     * @param map       the map: its lines, points and forbidden lines and areas
     * @param clearance how far the robot's centre keeps from them, mm
     */
    MapRoute(ArMap map, double clearance) {
        for (ArMapObject obj : map.findMapObjectsOfType("ForbiddenLine")) {
            forbidden.add(obj.getFromToSegment());
        }
        for (ArMapObject obj : map.findMapObjectsOfType("ForbiddenArea")) {
            forbidden.addAll(obj.getFromToSegments());
        }
        List<ArLineSegment> walls = new ArrayList<>(map.getLines());
        walls.addAll(forbidden);
        double[] box = bounds(map, walls, clearance);
        double extent = (box[2] - box[0]) * (box[3] - box[1]);
        this.cell = Math.max(CELL, Math.sqrt(extent / MAX_CELLS));
        this.minX = box[0];
        this.minY = box[1];
        this.width = (int) Math.ceil((box[2] - box[0]) / cell) + 1;
        this.height = (int) Math.ceil((box[3] - box[1]) / cell) + 1;
        this.grid = new byte[width * height];
        for (ArLineSegment s : walls) {
            drawLine(s.getX1(), s.getY1(), s.getX2(), s.getY2());
        }
        for (ArPose p : map.getPoints()) {
            block(cx(p.getX()), cy(p.getY()));
        }
        grow((int) Math.ceil(clearance / cell));
    }

    /** @return the forbidden segments: the lines, and each area's four sides */
    List<ArLineSegment> forbidden() {
        return forbidden;
    }

    /**
     * @param from where the robot is
     * @param to   the goal
     * @return the waypoints to drive through, the goal last; null if no route was found
     */
    List<ArPose> plan(ArPose from, ArPose to) {
        int start = index(cx(from.getX()), cy(from.getY()));
        int goal = index(cx(to.getX()), cy(to.getY()));
        if (start < 0 || goal < 0 || grid[start] == BLOCKED || grid[goal] == BLOCKED) {
            return null;
        }
        int[] cells = search(start, goal);
        if (cells == null) {
            return null;
        }
        // nearBefore[i]: the path's cells within the clearance before its i-th
        int[] nearBefore = new int[cells.length + 1];
        for (int i = 0; i < cells.length; i++) {
            nearBefore[i + 1] = nearBefore[i] + (grid[cells[i]] == NEAR ? 1 : 0);
        }
        List<ArPose> route = new ArrayList<>();
        int at = 0;
        while (at < cells.length - 1) {
            int next = at + 1;
            while (next + 1 < cells.length
                    && clear(cells[at], cells[next + 1], nearBefore[next + 2] - nearBefore[at])) {
                next++;
            }
            if (next < cells.length - 1) {
                route.add(new ArPose(x(cells[next] % width), y(cells[next] / width)));
            }
            at = next;
        }
        route.add(new ArPose(to.getX(), to.getY()));
        return route;
    }

    /** A* over the grid, eight neighbours; the cells from start to goal, or null. */
    private int[] search(int start, int goal) {
        double[] cost = new double[grid.length];
        Arrays.fill(cost, Double.MAX_VALUE);
        int[] came = new int[grid.length];
        cost[start] = 0;
        PriorityQueue<double[]> open = new PriorityQueue<>((a, b) -> Double.compare(a[0], b[0]));
        open.add(new double[] {heuristic(start, goal), start});
        while (!open.isEmpty()) {
            double[] head = open.poll();
            int c = (int) head[1];
            if (c == goal) {
                return path(came, start, goal);
            }
            if (head[0] > cost[c] + heuristic(c, goal) + 1e-9) {
                continue; // a stale entry
            }
            int cxi = c % width;
            int cyi = c / width;
            for (int dy = -1; dy <= 1; dy++) {
                for (int dx = -1; dx <= 1; dx++) {
                    int n = index(cxi + dx, cyi + dy);
                    if ((dx == 0 && dy == 0) || n < 0 || grid[n] == BLOCKED) {
                        continue;
                    }
                    double step = (dx != 0 && dy != 0 ? Math.sqrt(2) : 1) * (grid[n] == NEAR ? NEAR_COST : 1);
                    if (cost[c] + step < cost[n]) {
                        cost[n] = cost[c] + step;
                        came[n] = c;
                        open.add(new double[] {cost[n] + heuristic(n, goal), n});
                    }
                }
            }
        }
        return null;
    }

    private int[] path(int[] came, int start, int goal) {
        List<Integer> cells = new ArrayList<>();
        for (int c = goal; c != start; c = came[c]) {
            cells.add(c);
        }
        cells.add(start);
        int[] out = new int[cells.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = cells.get(out.length - 1 - i);
        }
        return out;
    }

    private double heuristic(int a, int b) {
        int dx = Math.abs(a % width - b % width);
        int dy = Math.abs(a / width - b / width);
        return Math.max(dx, dy) + (Math.sqrt(2) - 1) * Math.min(dx, dy);
    }

    /**
     * Whether the straight leg between two cells of the path is as clear as the path between them:
     * it meets nothing, and crosses no more cells within the clearance than the path does.
     */
    private boolean clear(int from, int to, int nearOnPath) {
        int[] near = {0};
        boolean open = walk(from % width, from / width, to % width, to / width, c -> {
            near[0] += grid[c] == NEAR ? 1 : 0;
            return grid[c] != BLOCKED;
        });
        return open && near[0] <= nearOnPath;
    }

    /** Visits the cells of a line (Bresenham's) while {@code visit} says go on; whether it got to the end. */
    private boolean walk(int x0, int y0, int x1, int y1, java.util.function.IntPredicate visit) {
        int dx = Math.abs(x1 - x0);
        int dy = -Math.abs(y1 - y0);
        int sx = x0 < x1 ? 1 : -1;
        int sy = y0 < y1 ? 1 : -1;
        int err = dx + dy;
        int x = x0;
        int y = y0;
        while (true) {
            int c = index(x, y);
            if (c >= 0 && !visit.test(c)) {
                return false;
            }
            if (x == x1 && y == y1) {
                return true;
            }
            int e2 = 2 * err;
            if (e2 >= dy) {
                err += dy;
                x += sx;
            }
            if (e2 <= dx) {
                err += dx;
                y += sy;
            }
        }
    }

    private void drawLine(double x1, double y1, double x2, double y2) {
        walk(cx(x1), cy(y1), cx(x2), cy(y2), c -> {
            grid[c] = BLOCKED;
            return true;
        });
    }

    private void block(int x, int y) {
        int c = index(x, y);
        if (c >= 0) {
            grid[c] = BLOCKED;
        }
    }

    /** Marks the free cells within {@code r} cells of a blocked one as near. */
    private void grow(int r) {
        int[] blocked = java.util.stream.IntStream.range(0, grid.length).filter(c -> grid[c] == BLOCKED).toArray();
        for (int c : blocked) {
            int x = c % width;
            int y = c / width;
            for (int dy = -r; dy <= r; dy++) {
                for (int dx = -r; dx <= r; dx++) {
                    int n = index(x + dx, y + dy);
                    if (n >= 0 && grid[n] == FREE && dx * dx + dy * dy <= r * r) {
                        grid[n] = NEAR;
                    }
                }
            }
        }
    }

    /** The box the grid covers: the map's lines and points, and a clearance round them. */
    private static double[] bounds(ArMap map, List<ArLineSegment> walls, double clearance) {
        double[] box = {Double.MAX_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (ArLineSegment s : walls) {
            include(box, s.getX1(), s.getY1());
            include(box, s.getX2(), s.getY2());
        }
        for (ArPose p : map.getPoints()) {
            include(box, p.getX(), p.getY());
        }
        for (ArMapObject obj : map.getMapObjects()) {
            include(box, obj.getPose().getX(), obj.getPose().getY());
        }
        if (box[0] > box[2]) {
            return new double[] {-clearance, -clearance, clearance, clearance};
        }
        return new double[] {box[0] - clearance, box[1] - clearance, box[2] + clearance, box[3] + clearance};
    }

    private static void include(double[] box, double x, double y) {
        box[0] = Math.min(box[0], x);
        box[1] = Math.min(box[1], y);
        box[2] = Math.max(box[2], x);
        box[3] = Math.max(box[3], y);
    }

    private int cx(double x) {
        return (int) Math.floor((x - minX) / cell);
    }

    private int cy(double y) {
        return (int) Math.floor((y - minY) / cell);
    }

    private double x(int cx) {
        return minX + (cx + 0.5) * cell;
    }

    private double y(int cy) {
        return minY + (cy + 0.5) * cell;
    }

    private int index(int x, int y) {
        return x < 0 || y < 0 || x >= width || y >= height ? -1 : y * width + x;
    }
}
