package robosim.env.camera;

import java.util.ArrayList;
import java.util.List;
import robosim.protocol.CameraView;

/**
 * Renders what a pinhole camera sees of a world of {@link ColoredShape}s, one image column at a
 * time: the column's ray is cast on the floor plane within the horizontal field of view, every
 * shape it meets is taken nearest first, and each paints the rows between the projections of its
 * foot and its top that nothing nearer has painted. So walls and robots hide what stands behind
 * them, and a tall thing is seen above a lower one in front of it.
 *
 * <p>Pixels are square: the vertical field of view follows from the horizontal one and the
 * image's 4:3 shape. Each column is treated as a vertical plane through the camera, which is exact
 * at tilt 0 and a close approximation at the small tilts a robot's camera works at.
 */
public final class CameraImage {
    /** A pixel that sees nothing coloured. */
    public static final int EMPTY = -1;
    /** The farthest a camera sees, mm: past it, a thing covers well under a pixel. */
    public static final double MAX_RANGE = 30_000;

    private static final int W = CameraView.IMAGE_WIDTH;
    private static final int H = CameraView.IMAGE_HEIGHT;

    private CameraImage() {
    }

    /**
     * @param x           the lens's x, mm
     * @param y           the lens's y, mm
     * @param height      the lens's height above the floor, mm
     * @param direction   where the lens points on the floor plane, radians (heading plus pan)
     * @param tilt        radians, positive up
     * @param fieldOfView the horizontal field of view, radians
     * @param shapes      what there is to see
     * @param ownBody     the body the camera is mounted on, which it does not see; −1 for none
     * @return the image, row by row from the top left: each pixel's colour 0xrrggbb or {@link #EMPTY}
     */
    public static int[] render(double x, double y, double height, double direction, double tilt,
                               double fieldOfView, List<ColoredShape> shapes, int ownBody) {
        List<ColoredShape> near = new ArrayList<>();
        for (ColoredShape s : shapes) {
            if ((ownBody < 0 || s.owner() != ownBody) && s.near(x, y, MAX_RANGE)
                    && s.mayBeWithin(x, y, direction, fieldOfView / 2)) {
                near.add(s);
            }
        }
        int[] image = new int[W * H];
        java.util.Arrays.fill(image, EMPTY);
        double halfWidth = Math.tan(fieldOfView / 2);
        double halfHeight = halfWidth * H / W;
        double[] dist = new double[near.size()];
        Integer[] hits = new Integer[near.size()];
        for (int u = 0; u < W; u++) {
            double offset = -Math.atan(columnCentre(u) * halfWidth);
            double dx = Math.cos(direction + offset);
            double dy = Math.sin(direction + offset);
            int count = 0;
            for (int k = 0; k < near.size(); k++) {
                dist[k] = near.get(k).hit(x, y, dx, dy);
                if (dist[k] <= MAX_RANGE) {
                    hits[count++] = k;
                }
            }
            // nearest first; equal distances in the order the shapes were given, so runs repeat exactly
            java.util.Arrays.sort(hits, 0, count, (a, b) -> dist[a] != dist[b] ? Double.compare(dist[a], dist[b])
                    : Integer.compare(a, b));
            boolean[] painted = new boolean[H];
            int left = H;
            for (int k = 0; k < count && left > 0; k++) {
                double d = dist[hits[k]];
                ColoredShape s = near.get(hits[k]);
                double[] span = verticalSpan(d * Math.cos(offset), -height, s.height() - height, tilt);
                if (span == null) {
                    continue;
                }
                for (int v = 0; v < H; v++) {
                    double yc = rowCentre(v) * halfHeight;
                    if (!painted[v] && yc >= span[0] && yc <= span[1]) {
                        painted[v] = true;
                        left--;
                        image[v * W + u] = s.rgb() == ColoredShape.NO_COLOR ? EMPTY : s.rgb();
                    }
                }
            }
        }
        return image;
    }

    /** @return column u's centre from −1 (left edge) to 1 (right edge) */
    static double columnCentre(int u) {
        return (u + 0.5 - W / 2.0) / (W / 2.0);
    }

    /** @return row v's centre from 1 (top edge) to −1 (bottom edge) */
    static double rowCentre(int v) {
        return (H / 2.0 - (v + 0.5)) / (H / 2.0);
    }

    /**
     * The image-plane heights (tangent units) of the lowest and highest points of a vertical
     * segment at forward depth {@code depth}, from {@code low} to {@code high} mm relative to the
     * lens, seen with a tilt; the part behind the lens is cut off.
     *
     * @return {bottom, top}, or null if all of it is behind the lens
     */
    static double[] verticalSpan(double depth, double low, double high, double tilt) {
        double c = Math.cos(tilt);
        double s = Math.sin(tilt);
        double bottom = Double.NEGATIVE_INFINITY;
        double top = Double.POSITIVE_INFINITY;
        // in front of the lens means depth·cos(tilt) + up·sin(tilt) > 0
        if (s > 0) {
            low = Math.max(low, -depth * c / s);
        } else if (s < 0) {
            high = Math.min(high, -depth * c / s);
        }
        if (low >= high) {
            return null;
        }
        if (depth * c + low * s > 1e-9) {
            bottom = (low * c - depth * s) / (depth * c + low * s);
        }
        if (depth * c + high * s > 1e-9) {
            top = (high * c - depth * s) / (depth * c + high * s);
        }
        return new double[] {bottom, top};
    }
}
