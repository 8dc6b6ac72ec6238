package robosim.geometry;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.index.strtree.STRtree;

/**
 * The order of the leaves of a JTS {@link STRtree} (of the default node capacity) built on items
 * with given envelopes: the order in which such a tree answers a query, leaving out the items
 * whose envelope misses it. Worked out as JTS builds the tree, level by level (sort the level by
 * the x of the envelopes' centres, cut it into vertical slices, sort each slice by the centres' y,
 * cut it into nodes of ten, until one node is left), but on primitive arrays: a few bytes per item
 * instead of the tree's objects, and a radix sort instead of a sort by comparator.
 *
 * <p>The sorts are stable, as JTS's are, and compare the centres as JTS does (-0.0 equal to 0.0), so
 * the order is JTS's own. A centre that is not a number has no order to copy; items with a
 * coordinate that is not finite are ordered by an STRtree itself.
 */
final class StrOrder {
    /** The node capacity of a default STRtree. */
    static final int NODE_CAPACITY = 10;

    private StrOrder() {
    }

    /** One level's nodes: its children in the order of their nodes, each node's first child, its bounds. */
    private record Level(int[] children, int[] first, double[] boxes) {
        int size() {
            return first.length - 1;
        }
    }

    /**
     * @param boxes four numbers per item, {@code xa, ya, xb, yb}: its envelope is the box spanned by
     *              the points (xa, ya) and (xb, yb), as {@code new Envelope(xa, xb, ya, yb)} makes it
     * @return the items' indexes in the order of the leaves of an STRtree of them
     */
    static int[] leafOrder(double[] boxes) {
        int n = boxes.length / 4;
        if (n == 0) {
            return new int[0];
        }
        for (double v : boxes) {
            if (!Double.isFinite(v)) {
                return treeOrder(boxes);
            }
        }
        List<Level> levels = new ArrayList<>();
        double[] bounds = boxes;
        do {
            Level level = parents(bounds);
            levels.add(level);
            bounds = level.boxes;
        } while (levels.get(levels.size() - 1).size() > 1);
        return leaves(levels);
    }

    /** The nodes one level up from children with these boxes, as {@code STRtree.createParentBoundables} makes them. */
    private static Level parents(double[] boxes) {
        int m = boxes.length / 4;
        long[] keys = new long[m];
        int[] order = new int[m];
        for (int i = 0; i < m; i++) {
            keys[i] = KeyOrder.key(centre(boxes, 4 * i));
            order[i] = i;
        }
        long[] keyScratch = new long[m];
        int[] orderScratch = new int[m];
        KeyOrder.sort(keys, order, 0, m, keyScratch, orderScratch);
        int leafCount = (int) Math.ceil(m / (double) NODE_CAPACITY);
        int sliceCount = (int) Math.ceil(Math.sqrt(leafCount));
        int sliceCapacity = (int) Math.ceil(m / (double) sliceCount);
        // each slice's last node may be short: at most one node more per slice than leafCount
        int[] first = new int[leafCount + sliceCount + 1];
        int nodes = 0;
        for (int from = 0; from < m; from += sliceCapacity) {
            int to = Math.min(m, from + sliceCapacity);
            for (int i = from; i < to; i++) {
                keys[i] = KeyOrder.key(centre(boxes, 4 * order[i] + 1));
            }
            KeyOrder.sort(keys, order, from, to, keyScratch, orderScratch);
            for (int start = from; start < to; start += NODE_CAPACITY) {
                first[nodes++] = start;
            }
        }
        first[nodes] = m;
        int[] firsts = Arrays.copyOf(first, nodes + 1);
        return new Level(order, firsts, nodeBoxes(boxes, order, firsts));
    }

    /** @return the centre of a box along one axis, as STRtree's comparators take it */
    private static double centre(double[] boxes, int at) {
        return (lo(boxes, at) + hi(boxes, at)) / 2d;
    }

    /** The lower of a box's two values along an axis, as {@link Envelope}'s constructor picks it. */
    private static double lo(double[] boxes, int at) {
        return boxes[at] < boxes[at + 2] ? boxes[at] : boxes[at + 2];
    }

    private static double hi(double[] boxes, int at) {
        return boxes[at] < boxes[at + 2] ? boxes[at + 2] : boxes[at];
    }

    /** Each node's bounds: its children's boxes joined in order, as {@code Envelope.expandToInclude} joins them. */
    private static double[] nodeBoxes(double[] boxes, int[] order, int[] first) {
        int nodes = first.length - 1;
        double[] out = new double[4 * nodes];
        for (int p = 0; p < nodes; p++) {
            int c = 4 * order[first[p]];
            double minX = lo(boxes, c);
            double minY = lo(boxes, c + 1);
            double maxX = hi(boxes, c);
            double maxY = hi(boxes, c + 1);
            for (int k = first[p] + 1; k < first[p + 1]; k++) {
                c = 4 * order[k];
                double v = lo(boxes, c);
                minX = v < minX ? v : minX;
                v = hi(boxes, c);
                maxX = v > maxX ? v : maxX;
                v = lo(boxes, c + 1);
                minY = v < minY ? v : minY;
                v = hi(boxes, c + 1);
                maxY = v > maxY ? v : maxY;
            }
            out[4 * p] = minX;
            out[4 * p + 1] = minY;
            out[4 * p + 2] = maxX;
            out[4 * p + 3] = maxY;
        }
        return out;
    }

    /** Walks down from the root, each node replaced by its children in order, to the items. */
    private static int[] leaves(List<Level> levels) {
        int[] nodes = {0};
        for (int l = levels.size() - 1; l >= 0; l--) {
            Level level = levels.get(l);
            int[] below = new int[level.children.length];
            int n = 0;
            for (int node : nodes) {
                for (int k = level.first[node]; k < level.first[node + 1]; k++) {
                    below[n++] = level.children[k];
                }
            }
            nodes = below;
        }
        return nodes;
    }

    /** The order an STRtree itself gives, for boxes with a coordinate that is not finite. */
    private static int[] treeOrder(double[] boxes) {
        STRtree tree = new STRtree();
        for (int i = 0; i < boxes.length / 4; i++) {
            tree.insert(new Envelope(boxes[4 * i], boxes[4 * i + 2], boxes[4 * i + 1], boxes[4 * i + 3]), i);
        }
        List<?> all = tree.query(new Envelope(Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY));
        return all.stream().mapToInt(o -> (Integer) o).toArray();
    }
}
