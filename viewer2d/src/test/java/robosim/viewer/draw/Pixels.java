package robosim.viewer.draw;

import java.awt.Color;
import java.awt.image.BufferedImage;

/** Reads and compares the pixels of rendered images. */
public final class Pixels {
    private Pixels() {
    }

    public static Color at(BufferedImage image, int x, int y) {
        return new Color(image.getRGB(x, y));
    }

    /** @return how much redder than blue the pixel is: the background's is 4, a glow's far more */
    public static int warmth(BufferedImage image, int x, int y) {
        Color c = at(image, x, y);
        return c.getRed() - c.getBlue();
    }

    /** @return how many pixels differ between the images in the box [x0, x1) x [y0, y1) */
    public static int differing(BufferedImage a, BufferedImage b, int x0, int y0, int x1, int y1) {
        int n = 0;
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                if (a.getRGB(x, y) != b.getRGB(x, y)) {
                    n++;
                }
            }
        }
        return n;
    }

    /** @return how many pixels differ anywhere in two images of the same size */
    public static int differing(BufferedImage a, BufferedImage b) {
        return differing(a, b, 0, 0, a.getWidth(), a.getHeight());
    }
}
