package robosim.examples.goldfinder;

import java.util.ArrayDeque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * What a Gold robot knows of the maze: the cells whose walls have been sensed (by it or a
 * teammate), and where each teammate is and is going. Cells are keyed by column and row.
 */
final class MazeKnowledge {
    /** A teammate's last reported place and target. */
    record Mate(int x, int y, int nextX, int nextY) { }

    private final Map<Long, Integer> openSides = new HashMap<>();
    private final Map<String, Mate> mates = new HashMap<>();

    static long key(int x, int y) {
        return ((long) x << 32) ^ (y & 0xffffffffL);
    }

    void sensed(int x, int y, int open) {
        openSides.put(key(x, y), open);
    }

    boolean isSensed(int x, int y) {
        return openSides.containsKey(key(x, y));
    }

    boolean open(int x, int y, int dir) {
        Integer o = openSides.get(key(x, y));
        return o != null && (o & (1 << dir)) != 0;
    }

    void mate(String robot, Mate m) {
        mates.put(robot, m);
    }

    /** Whether a teammate stands in or is heading for a cell. */
    boolean claimedByMate(int x, int y) {
        for (Mate m : mates.values()) {
            if ((m.x() == x && m.y() == y) || (m.nextX() == x && m.nextY() == y)) {
                return true;
            }
        }
        return false;
    }

    /** The teammate standing in a cell, or null. */
    String occupant(int x, int y) {
        for (Map.Entry<String, Mate> e : mates.entrySet()) {
            if (e.getValue().x() == x && e.getValue().y() == y) {
                return e.getKey();
            }
        }
        return null;
    }

    Mate mate(String robot) {
        return mates.get(robot);
    }

    /** Open, unsensed neighbours of a sensed cell that no teammate has claimed: the frontier there. */
    boolean hasFrontier(int x, int y) {
        for (int d = 0; d < 4; d++) {
            int nx = x + Maze.DIRECTIONS[d][0];
            int ny = y + Maze.DIRECTIONS[d][1];
            if (open(x, y, d) && !isSensed(nx, ny) && !claimedByMate(nx, ny)) {
                return true;
            }
        }
        return false;
    }

    /**
     * The first step of a shortest known path from (x, y) to the nearest cell with a frontier,
     * trying directions in {@code order}; paths through cells in {@code avoid} are not taken.
     *
     * @return the direction of the first step, or -1 if no frontier is reachable
     */
    int towardsFrontier(int x, int y, int[] order, Set<Long> avoid) {
        ArrayDeque<int[]> queue = new ArrayDeque<>();
        Set<Long> seen = new HashSet<>();
        seen.add(key(x, y));
        queue.add(new int[] {x, y, -1});
        while (!queue.isEmpty()) {
            int[] c = queue.poll();
            if (c[2] >= 0 && hasFrontier(c[0], c[1])) {
                return c[2];
            }
            for (int d : order) {
                int nx = c[0] + Maze.DIRECTIONS[d][0];
                int ny = c[1] + Maze.DIRECTIONS[d][1];
                long k = key(nx, ny);
                if (open(c[0], c[1], d) && isSensed(nx, ny) && !seen.contains(k) && !avoid.contains(k)) {
                    seen.add(k);
                    queue.add(new int[] {nx, ny, c[2] < 0 ? d : c[2]});
                }
            }
        }
        return -1;
    }

    /** The names of the teammates heard from. */
    List<String> mates() {
        return mates.keySet().stream().sorted().toList();
    }
}
