package robosim.env.camera;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import robosim.protocol.CameraView;
import robosim.protocol.ColorBlob;

/**
 * Finds ACTS's blobs in an image: for each channel bound to a colour, the regions of pixels of
 * that colour connected through their four neighbours, largest first (ties: the topmost, then the
 * leftmost), at most {@value CameraView#MAX_BLOBS} per channel, as ACTS reports them through ARIA's
 * ArACTS.cpp.
 */
public final class BlobFinder {
    private static final int W = CameraView.IMAGE_WIDTH;
    private static final int H = CameraView.IMAGE_HEIGHT;

    private BlobFinder() {
    }

    /**
     * @param image    the image from {@link CameraImage#render}
     * @param channels each channel's colour 0xrrggbb by index (channel 1 at index 0), or
     *                 {@link ColoredShape#NO_COLOR} for a free channel
     * @return the blobs by channel, then largest first
     */
    public static List<ColorBlob> find(int[] image, int[] channels) {
        List<ColorBlob> all = new ArrayList<>();
        for (int c = 0; c < channels.length; c++) {
            if (channels[c] != ColoredShape.NO_COLOR) {
                all.addAll(channel(image, c + 1, channels[c]));
            }
        }
        return all;
    }

    private static List<ColorBlob> channel(int[] image, int channel, int rgb) {
        boolean[] seen = new boolean[image.length];
        int[] stack = new int[image.length];
        List<ColorBlob> blobs = new ArrayList<>();
        for (int start = 0; start < image.length; start++) {
            if (seen[start] || image[start] != rgb) {
                continue;
            }
            int top = 0;
            stack[top++] = start;
            seen[start] = true;
            long sumX = 0;
            long sumY = 0;
            int area = 0;
            int left = W;
            int right = -1;
            int upper = H;
            int lower = -1;
            while (top > 0) {
                int p = stack[--top];
                int px = p % W;
                int py = p / W;
                area++;
                sumX += px;
                sumY += py;
                left = Math.min(left, px);
                right = Math.max(right, px);
                upper = Math.min(upper, py);
                lower = Math.max(lower, py);
                top = push(image, seen, stack, top, rgb, px - 1, py);
                top = push(image, seen, stack, top, rgb, px + 1, py);
                top = push(image, seen, stack, top, rgb, px, py - 1);
                top = push(image, seen, stack, top, rgb, px, py + 1);
            }
            blobs.add(new ColorBlob(channel, area, (int) Math.round((double) sumX / area),
                    (int) Math.round((double) sumY / area), left, right, upper, lower));
        }
        blobs.sort(Comparator.comparingInt(ColorBlob::area).reversed()
                .thenComparingInt(ColorBlob::top).thenComparingInt(ColorBlob::left));
        return blobs.size() > CameraView.MAX_BLOBS ? blobs.subList(0, CameraView.MAX_BLOBS) : blobs;
    }

    private static int push(int[] image, boolean[] seen, int[] stack, int top, int rgb, int x, int y) {
        if (x < 0 || x >= W || y < 0 || y >= H) {
            return top;
        }
        int p = y * W + x;
        if (seen[p] || image[p] != rgb) {
            return top;
        }
        seen[p] = true;
        stack[top] = p;
        return top + 1;
    }
}
