package robosim.examples.goldfinder;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * What a Gold robot knows of the maze: the cells whose walls have been sensed (by it or a
 * teammate), and what each teammate last said of itself: where it is, where it goes next, which
 * frontier it has claimed, and when it was heard. Cells are keyed by column and row.
 *
 * <p>A frontier is a cell nobody has sensed behind an open side of a sensed cell: the edge of
 * what the team knows. Paths lead through sensed cells only, and may end in a frontier.
 */
final class MazeKnowledge {
    /** No cell: a teammate that is not moving or has claimed nothing. */
    static final int NONE = Integer.MIN_VALUE;

    /**
     * A teammate's last report of itself.
     *
     * @param x      its cell's column
     * @param y      its cell's row
     * @param route  the keys of the cells ahead it has committed to drive through, nearest first
     * @param claimX the column of the frontier it has claimed, or {@link #NONE}
     * @param claimY the row of that frontier
     * @param heard  the step at which this robot heard the report
     * @param want   the key of the cell it waits to enter, or -1
     * @param target the key of the frontier it claimed or follows, or -1
     */
    record Mate(int x, int y, List<Long> route, int claimX, int claimY, long heard, long want, long target) {
        /** Keeps a copy of the route. */
        Mate {
            route = List.copyOf(route);
        }

        /** A teammate that waits for no cell and heads for its claim, if any. */
        Mate(int x, int y, List<Long> route, int claimX, int claimY, long heard) {
            this(x, y, route, claimX, claimY, heard, -1, claimX == NONE ? -1 : key(claimX, claimY));
        }

        /** A teammate that stands in a cell and has claimed nothing. */
        Mate(int x, int y, long heard) {
            this(x, y, List.of(), NONE, NONE, heard);
        }

        boolean moving() {
            return !route.isEmpty();
        }

        boolean claims() {
            return claimX != NONE;
        }

        /** The cells it holds: the one it stands in and every cell ahead it has committed to. */
        List<Long> cells() {
            List<Long> out = new ArrayList<>();
            out.add(key(x, y));
            out.addAll(route);
            return out;
        }

        /** Whether it stands in, or has committed to drive through, the cell. */
        boolean holds(int cx, int cy) {
            return cells().contains(key(cx, cy));
        }
    }

    /** Open sides by cell, in key order so that every walk over them is the same on every run. */
    private final Map<Long, Integer> openSides = new TreeMap<>();
    private final Map<String, Mate> mates = new TreeMap<>();

    static long key(int x, int y) {
        return ((long) x << 32) ^ (y & 0xffffffffL);
    }

    static int keyX(long key) {
        return (int) (key >> 32);
    }

    static int keyY(long key) {
        return (int) key;
    }

    /**
     * @param x    the cell's column
     * @param y    its row
     * @param open bit d set when side d (0 east, 1 north, 2 west, 3 south) is open
     */
    void sensed(int x, int y, int open) {
        openSides.put(key(x, y), open);
    }

    boolean isSensed(int x, int y) {
        return openSides.containsKey(key(x, y));
    }

    /** @return the cell's open sides, or -1 if nobody has sensed it */
    int openSides(int x, int y) {
        Integer o = openSides.get(key(x, y));
        return o == null ? -1 : o;
    }

    /**
     * Whether a side of a sensed cell is open. A side is open when either cell it parts says so: a
     * teammate passing by can make an open side look closed, never a wall look open.
     */
    boolean open(int x, int y, int dir) {
        Integer o = openSides.get(key(x, y));
        if (o == null) {
            return false;
        }
        if ((o & (1 << dir)) != 0) {
            return true;
        }
        Integer other = openSides.get(key(x + Directions.dx(dir), y + Directions.dy(dir)));
        return other != null && (other & (1 << ((dir + 2) % 4))) != 0;
    }

    /** @return how many cells are sensed */
    int sensedCount() {
        return openSides.size();
    }

    /** @return the sensed cells' keys, in key order */
    Set<Long> sensedCells() {
        return openSides.keySet();
    }

    /** Whether the cell is a frontier: unsensed, behind an open side of a sensed neighbour. */
    boolean isFrontier(int x, int y) {
        if (isSensed(x, y)) {
            return false;
        }
        for (int d = 0; d < 4; d++) {
            if (open(x + Directions.dx(d), y + Directions.dy(d), (d + 2) % 4)) {
                return true;
            }
        }
        return false;
    }

    /** @return every frontier cell's key, in key order */
    List<Long> frontiers() {
        Set<Long> out = new TreeSet<>();
        for (Map.Entry<Long, Integer> e : openSides.entrySet()) {
            int x = keyX(e.getKey());
            int y = keyY(e.getKey());
            for (int d = 0; d < 4; d++) {
                int nx = x + Directions.dx(d);
                int ny = y + Directions.dy(d);
                if ((e.getValue() & (1 << d)) != 0 && !isSensed(nx, ny)) {
                    out.add(key(nx, ny));
                }
            }
        }
        return new ArrayList<>(out);
    }

    /**
     * Path lengths, in cells, from one cell over the known maze: through sensed cells, ending in
     * frontiers (which are reached but not gone through).
     *
     * @param x       the start's column
     * @param y       the start's row
     * @param order   the order in which directions are tried, which decides between equal paths
     * @param blocked cells not to pass (they are not reached either)
     * @return distance and first step by cell key, in the order the cells were reached
     */
    Map<Long, Reach> reach(int x, int y, int[] order, Set<Long> blocked) {
        Map<Long, Reach> out = new LinkedHashMap<>();
        ArrayDeque<long[]> queue = new ArrayDeque<>();
        out.put(key(x, y), new Reach(0, -1, -1));
        queue.add(new long[] {x, y});
        while (!queue.isEmpty()) {
            long[] c = queue.poll();
            int cx = (int) c[0];
            int cy = (int) c[1];
            Reach here = out.get(key(cx, cy));
            if (!isSensed(cx, cy)) {
                continue;
            }
            for (int d : order) {
                int nx = cx + Directions.dx(d);
                int ny = cy + Directions.dy(d);
                long k = key(nx, ny);
                if (open(cx, cy, d) && !out.containsKey(k) && !blocked.contains(k)) {
                    out.put(k, new Reach(here.cells() + 1, here.first() < 0 ? d : here.first(), d));
                    queue.add(new long[] {nx, ny});
                }
            }
        }
        return out;
    }

    /**
     * How far a cell is, and which way to start.
     *
     * @param cells steps in cells
     * @param first the direction of the first step from the start, or -1 at the start
     * @param last  the direction of the last step into the cell, or -1 at the start
     */
    record Reach(int cells, int first, int last) { }

    /**
     * The cells of a shortest known path, from (x, y) exclusive to (tx, ty) inclusive.
     *
     * @return the cells' keys in order, or an empty list if there is no known path
     */
    List<Long> path(int x, int y, int tx, int ty, int[] order, Set<Long> blocked) {
        Map<Long, Reach> reach = reach(x, y, order, blocked);
        if (!reach.containsKey(key(tx, ty))) {
            return List.of();
        }
        List<Long> out = new ArrayList<>();
        int cx = tx;
        int cy = ty;
        while (cx != x || cy != y) {
            out.add(0, key(cx, cy));
            int d = reach.get(key(cx, cy)).last();
            cx -= Directions.dx(d);
            cy -= Directions.dy(d);
        }
        return out;
    }

    /**
     * @param robot the teammate
     * @param m     what it last said of itself
     */
    void mate(String robot, Mate m) {
        mates.put(robot, m);
    }

    /** @return what a teammate last said of itself, or null if it was never heard */
    Mate mate(String robot) {
        return mates.get(robot);
    }

    /** @return the names of the teammates heard from, sorted */
    List<String> mates() {
        return new ArrayList<>(mates.keySet());
    }

    /** The teammate standing in or driving into a cell, or null. */
    String holder(int x, int y) {
        for (Map.Entry<String, Mate> e : mates.entrySet()) {
            if (e.getValue().holds(x, y)) {
                return e.getKey();
            }
        }
        return null;
    }

    /**
     * Whether a teammate holds a cell against a robot coming into it from cell {@code from}: it
     * has committed to the cell, or it stands there, unless it is leaving it by another side than
     * towards {@code from} (then the robot may follow it in, its laser keeping the distance).
     */
    boolean heldAgainst(long cell, long from) {
        for (Mate m : mates.values()) {
            if (m.route().contains(cell)) {
                return true;
            }
            if (key(m.x(), m.y()) == cell && !(m.moving() && m.route().get(0) != from)) {
                return true;
            }
        }
        return false;
    }

    /** @return the cells teammates stand in or drive into */
    Set<Long> held() {
        Set<Long> out = new TreeSet<>();
        for (Mate m : mates.values()) {
            out.addAll(m.cells());
        }
        return out;
    }
}
