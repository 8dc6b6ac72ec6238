package robosim.aria;

import java.util.Arrays;

/** Which of n equal sectors of the circle a heading has been in, as ARIA's ArSectors (ariaUtil.h). */
final class Sectors {
    private final boolean[] seen;

    Sectors(int count) {
        seen = new boolean[count];
    }

    void clear() {
        Arrays.fill(seen, false);
    }

    /** @param degrees a heading */
    void update(double degrees) {
        double a = ((degrees % 360) + 360) % 360;
        int sector = (int) Math.floor(a) / (360 / seen.length);
        seen[Math.min(sector, seen.length - 1)] = true;
    }

    /** @return whether the heading has been in every sector since the last clear */
    boolean didAll() {
        for (boolean s : seen) {
            if (!s) {
                return false;
            }
        }
        return true;
    }
}
