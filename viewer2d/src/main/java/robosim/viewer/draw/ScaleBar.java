package robosim.viewer.draw;

import java.util.Locale;

/**
 * Round lengths for the scale bar and the grid: 1, 2 or 5 times a power of ten, in mm, and how
 * they are written ({@code "500 mm"}, {@code "2 m"}).
 */
public final class ScaleBar {
    private ScaleBar() {
    }

    /**
     * @param limitMm the longest length allowed, mm, greater than 0
     * @return the longest round length (1, 2 or 5 times a power of ten mm) not above the limit, at
     *         least 1 mm
     */
    public static double roundLength(double limitMm) {
        if (!(limitMm >= 1) || !Double.isFinite(limitMm)) {
            return 1;
        }
        double power = Math.pow(10, Math.floor(Math.log10(limitMm)));
        for (double m : new double[] {5, 2, 1}) {
            if (m * power <= limitMm * (1 + 1e-9)) {
                return m * power;
            }
        }
        return power;
    }

    /**
     * The scale bar's length for an image: a round length at most a quarter of its width.
     *
     * @param scale   pixels per mm
     * @param widthPx the image's width, px
     * @return the bar's length, mm
     */
    public static double barLength(double scale, int widthPx) {
        return roundLength(widthPx / 4.0 / scale);
    }

    /**
     * The grid's spacing: a round length that puts about eight cells along the world's longer side.
     *
     * @param worldWidthMm the world's longer side, mm
     * @return the spacing, mm
     */
    public static double gridSpacing(double worldWidthMm) {
        return roundLength(worldWidthMm / 8);
    }

    /**
     * @param mm a round length
     * @return it written in metres from 1 m up, in mm below
     */
    public static String label(double mm) {
        if (mm >= 1000) {
            double m = mm / 1000;
            return (m == Math.rint(m) ? String.format(Locale.ROOT, "%.0f", m) : String.format(Locale.ROOT, "%s", m)) + " m";
        }
        return String.format(Locale.ROOT, "%.0f mm", mm);
    }
}
