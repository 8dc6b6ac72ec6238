package robosim.geometry;

import java.util.Arrays;
import java.util.Objects;
import org.locationtech.jts.geom.Envelope;

/**
 * Items (the moving bodies, or the static edges) by the cells of a uniform grid, so that a query
 * looks only at the items near it instead of at all of them. An item is listed in every cell its
 * envelope overlaps. Cell coordinates are clamped to the grid: an item or a query outside it falls
 * into the border cells, so answers stay complete there, only slower.
 *
 * <p>A query answers the ids of every item whose envelope's cells overlap the query's, so every
 * item whose envelope intersects the query's envelope is among them (the mapping from a coordinate
 * to its cell is monotonic); the caller applies its exact test. Ids come in ascending order, so
 * whatever the caller does with them happens in id order, as a scan of all items would.
 *
 * <p>Changes ({@link #add}, {@link #move}) must not run during queries; queries allocate their own
 * answer and may run concurrently with each other.
 */
final class CellGrid {
    /** At most this many cells; a larger extent gets larger cells. */
    static final int MAX_CELLS = 1 << 20;

    private final double minX;
    private final double minY;
    private final double cell;
    private final int nx;
    private final int ny;
    /** Per cell, the ids of the items in it (in no particular order), and how many there are. */
    private final int[][] cells;
    private final int[] counts;
    /** Per item: the first and last cell column and row of its envelope. */
    private int[] ranges;
    private int size;

    /**
     * @param extent   the area the grid covers; must not be null
     * @param cellSize the side of a cell, mm, greater than 0; larger if the extent would need more
     *                 than {@value #MAX_CELLS} cells
     */
    CellGrid(Envelope extent, double cellSize) {
        this(extent, cellSize, 16);
    }

    /**
     * @param extent   the area the grid covers; must not be null
     * @param cellSize the side of a cell, mm, greater than 0; larger if the extent would need more
     *                 than {@value #MAX_CELLS} cells
     * @param expected how many items it will likely hold, so that their ranges need no regrowing
     */
    CellGrid(Envelope extent, double cellSize, int expected) {
        if (extent.isNull()) {
            throw new IllegalArgumentException("a body grid needs an extent");
        }
        double w = Math.max(extent.getWidth(), cellSize);
        double h = Math.max(extent.getHeight(), cellSize);
        double c = Math.max(cellSize, Math.sqrt(w * h / MAX_CELLS));
        while (Math.ceil(w / c) * Math.ceil(h / c) > MAX_CELLS) {
            c *= 1.25;
        }
        this.minX = extent.getMinX();
        this.minY = extent.getMinY();
        this.cell = c;
        this.nx = (int) Math.ceil(w / c);
        this.ny = (int) Math.ceil(h / c);
        this.cells = new int[nx * ny][];
        this.counts = new int[nx * ny];
        this.ranges = new int[4 * Math.max(1, expected)];
    }

    /** @return the side of a cell, mm */
    double cellSize() {
        return cell;
    }

    /** @return whether an envelope lies inside the grid's cells, so that no clamping happens */
    boolean covers(Envelope env) {
        return env.getMinX() >= minX && env.getMinY() >= minY
                && env.getMaxX() < minX + nx * cell && env.getMaxY() < minY + ny * cell;
    }

    private int column(double x) {
        double c = Math.floor((x - minX) / cell);
        return c < 0 ? 0 : c >= nx ? nx - 1 : (int) c;
    }

    private int row(double y) {
        double r = Math.floor((y - minY) / cell);
        return r < 0 ? 0 : r >= ny ? ny - 1 : (int) r;
    }

    /**
     * Lists a new item; ids must come in order 0, 1, 2, ...
     *
     * @param id  the item's id
     * @param env its envelope
     */
    void add(int id, Envelope env) {
        add(id, env.getMinX(), env.getMinY(), env.getMaxX(), env.getMaxY());
    }

    /**
     * Lists a new item; ids must come in order 0, 1, 2, ...
     *
     * @param id   the item's id
     * @param minX its envelope's least x
     * @param minY its least y
     * @param maxX its greatest x
     * @param maxY its greatest y
     */
    void add(int id, double minX, double minY, double maxX, double maxY) {
        if (id != size) {
            throw new IllegalArgumentException(id + " was supplied for id: the next item's id is " + size);
        }
        if (ranges.length < 4 * (size + 1)) {
            ranges = Arrays.copyOf(ranges, ranges.length * 2);
        }
        size++;
        int r = 4 * id;
        ranges[r] = column(minX);
        ranges[r + 1] = row(minY);
        ranges[r + 2] = column(maxX);
        ranges[r + 3] = row(maxY);
        insert(id);
    }

    /**
     * Moves an item to the cells of its new envelope.
     *
     * @param id  the item's id
     * @param env its new envelope
     */
    void move(int id, Envelope env) {
        int r = 4 * id;
        int x0 = column(env.getMinX());
        int y0 = row(env.getMinY());
        int x1 = column(env.getMaxX());
        int y1 = row(env.getMaxY());
        if (x0 == ranges[r] && y0 == ranges[r + 1] && x1 == ranges[r + 2] && y1 == ranges[r + 3]) {
            return;
        }
        remove(id);
        ranges[r] = x0;
        ranges[r + 1] = y0;
        ranges[r + 2] = x1;
        ranges[r + 3] = y1;
        insert(id);
    }

    private void insert(int id) {
        int r = 4 * id;
        for (int y = ranges[r + 1]; y <= ranges[r + 3]; y++) {
            for (int x = ranges[r]; x <= ranges[r + 2]; x++) {
                int c = y * nx + x;
                int[] ids = cells[c];
                if (ids == null) {
                    ids = new int[4];
                    cells[c] = ids;
                } else if (counts[c] == ids.length) {
                    ids = Arrays.copyOf(ids, ids.length * 2);
                    cells[c] = ids;
                }
                ids[counts[c]++] = id;
            }
        }
    }

    private void remove(int id) {
        int r = 4 * id;
        for (int y = ranges[r + 1]; y <= ranges[r + 3]; y++) {
            for (int x = ranges[r]; x <= ranges[r + 2]; x++) {
                int c = y * nx + x;
                int[] ids = cells[c];
                int n = counts[c];
                for (int i = 0; i < n; i++) {
                    if (ids[i] == id) {
                        ids[i] = ids[n - 1];
                        counts[c] = n - 1;
                        break;
                    }
                }
            }
        }
    }

    /** What {@link #walkRay} shows each cell a ray crosses. */
    interface RayCellVisitor {
        /**
         * @param ids   the ids of the cell's items (only the first {@code count} count)
         * @param count how many
         * @param exit  the distance along the ray at which it leaves the cell
         * @return whether to stop walking
         */
        boolean visit(int[] ids, int count, double exit);
    }

    /**
     * Visits the cells a ray crosses within {@code maxT}, nearest first (Amanatides and Woo's
     * walk), so that a caller looking for the nearest hit can stop once its best lies before the
     * cell it has come to. Only the part of the ray inside the grid is walked: every item lies
     * inside it, so nothing outside can be hit. Cells without items are passed over.
     *
     * @param ox      ray origin x, mm
     * @param oy      ray origin y, mm
     * @param dx      unit direction x
     * @param dy      unit direction y
     * @param maxT    how far along the ray to look, mm
     * @param visitor told each cell with items, nearest first
     */
    void walkRay(double ox, double oy, double dx, double dy, double maxT, RayCellVisitor visitor) {
        double gx1 = minX + nx * cell;
        double gy1 = minY + ny * cell;
        double t0 = 0;
        double t1 = maxT;
        if (dx == 0) {
            if (ox < minX || ox > gx1) {
                return;
            }
        } else {
            double a = (minX - ox) / dx;
            double b = (gx1 - ox) / dx;
            t0 = Math.max(t0, Math.min(a, b));
            t1 = Math.min(t1, Math.max(a, b));
        }
        if (dy == 0) {
            if (oy < minY || oy > gy1) {
                return;
            }
        } else {
            double a = (minY - oy) / dy;
            double b = (gy1 - oy) / dy;
            t0 = Math.max(t0, Math.min(a, b));
            t1 = Math.min(t1, Math.max(a, b));
        }
        if (t0 > t1) {
            return;
        }
        int cx = column(ox + dx * t0);
        int cy = row(oy + dy * t0);
        int stepX = dx > 0 ? 1 : -1;
        int stepY = dy > 0 ? 1 : -1;
        double nextX = dx == 0 ? Double.POSITIVE_INFINITY : (minX + (cx + (dx > 0 ? 1 : 0)) * cell - ox) / dx;
        double nextY = dy == 0 ? Double.POSITIVE_INFINITY : (minY + (cy + (dy > 0 ? 1 : 0)) * cell - oy) / dy;
        double deltaX = dx == 0 ? Double.POSITIVE_INFINITY : cell / Math.abs(dx);
        double deltaY = dy == 0 ? Double.POSITIVE_INFINITY : cell / Math.abs(dy);
        while (true) {
            double exit = Math.min(Math.min(nextX, nextY), t1);
            int c = cy * nx + cx;
            if (counts[c] > 0 && visitor.visit(cells[c], counts[c], exit)) {
                return;
            }
            if (exit >= t1) {
                return;
            }
            if (nextX < nextY) {
                cx += stepX;
                nextX += deltaX;
            } else {
                cy += stepY;
                nextY += deltaY;
            }
            if (cx < 0 || cx >= nx || cy < 0 || cy >= ny) {
                return;
            }
        }
    }

    /**
     * The items that may intersect an envelope.
     *
     * @param env the envelope looked in
     * @return the ids of every item whose cells overlap the envelope's, each once, ascending
     */
    int[] query(Envelope env) {
        Ids out = new Ids();
        query(env, out);
        return out.toArray();
    }

    /**
     * {@link #query(Envelope)} into a list of the caller's, which keeps its array from one query to
     * the next.
     *
     * @param env the envelope looked in
     * @param out emptied, then given the ids, ascending
     */
    void query(Envelope env, Ids out) {
        out.size = 0;
        if (env.isNull() || size == 0) {
            return;
        }
        int qx0 = column(env.getMinX());
        int qy0 = row(env.getMinY());
        int qx1 = column(env.getMaxX());
        int qy1 = row(env.getMaxY());
        for (int y = qy0; y <= qy1; y++) {
            for (int x = qx0; x <= qx1; x++) {
                int c = y * nx + x;
                int k = counts[c];
                if (k == 0) {
                    continue;
                }
                int[] ids = cells[c];
                for (int i = 0; i < k; i++) {
                    int id = ids[i];
                    int r = 4 * id;
                    // an item in several of these cells is taken only in the first of them
                    if (x == Math.max(ranges[r], qx0) && y == Math.max(ranges[r + 1], qy0)) {
                        out.add(id);
                    }
                }
            }
        }
        Arrays.sort(out.ids, 0, out.size);
    }

    /** A growing list of ids, kept by its owner from one query to the next. */
    static final class Ids {
        private int[] ids = new int[64];
        private int size;

        void add(int id) {
            if (size == ids.length) {
                ids = Arrays.copyOf(ids, size * 2);
            }
            ids[size++] = id;
        }

        /** @return the ids, in a new array of their number */
        int[] toArray() {
            return Arrays.copyOf(ids, size);
        }

        /** Forgets every id. */
        void clear() {
            size = 0;
        }

        /**
         * Keeps the first {@code n} ids, as a filter that wrote the ids it keeps over the list
         * with {@link #set} leaves them.
         */
        void truncate(int n) {
            size = Math.min(size, n);
        }

        /** Puts {@code id} at place {@code i}, below {@link #size}. */
        void set(int i, int id) {
            ids[Objects.checkIndex(i, size)] = id;
        }

        /** @return how many ids */
        int size() {
            return size;
        }

        /** @return the id at place {@code i} */
        int get(int i) {
            return ids[i];
        }
    }
}
