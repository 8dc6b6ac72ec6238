package robosim.protocol;

/**
 * The laser's part of a robot's state, while its laser is on: its latest scan.
 *
 * @param ranges the readings, mm, from its right (−90°) to its left (+90°)
 */
public record LaserReading(int[] ranges) {
    /** The reading of a laser that is off: no scan. */
    public static final LaserReading OFF = new LaserReading(new int[0]);

    /** Its key: absent reads as {@link #OFF}. */
    public static final StatePart<LaserReading> PART = new StatePart<>("laser", LaserReading.class, OFF);

    /** Checks the ranges are there. */
    public LaserReading {
        if (ranges == null) {
            throw new IllegalArgumentException("a laser reading needs its ranges");
        }
    }
}
