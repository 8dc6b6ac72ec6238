package robosim.env.sensors;

/**
 * Which sonar transducers fire in a step when the ring fires in sequence ({@code SetSonarCycle}),
 * as a Pioneer's firmware sequences its ring: the transducers form banks of
 * {@value #BANK_SIZE} by index (0–7, 8–15, ...), and each firing, every {@code msPerFiring} ms of
 * simulated time, fires the transducer in the same place of every bank, places in index order. A
 * P3's 16 sonars at ARCOS's 40 ms thus fire 0 and 8, then 1 and 9, ... and the whole ring every
 * 320 ms. The first reading after the robot is placed fires the whole ring.
 */
final class SonarSequence {
    /** How many transducers a bank holds: one of each bank fires at a time. */
    static final int BANK_SIZE = 8;

    private final PeriodicSensor clock;
    private final int transducers;
    private final int places;
    private Long lastMs;

    /**
     * @param msPerFiring simulated ms between firings, greater than 0
     * @param transducers the ring's transducers, at most 64
     */
    SonarSequence(long msPerFiring, int transducers) {
        this.clock = new PeriodicSensor(msPerFiring);
        this.transducers = transducers;
        this.places = Math.min(transducers, BANK_SIZE);
    }

    /**
     * @param timeMs the simulated time of this reading
     * @return the transducers that fire since the previous reading, bit i for transducer i
     */
    long fire(long timeMs) {
        Long last = lastMs;
        lastMs = timeMs;
        if (last == null) {
            return all();
        }
        long n = clock.firings(last, timeMs);
        if (n >= places) {
            return all();
        }
        long fired = 0;
        long first = clock.firstFiring(last, timeMs);
        for (long k = first; k < first + n; k++) {
            int place = (int) Math.floorMod(k, (long) places);
            for (int i = place; i < transducers; i += BANK_SIZE) {
                fired |= 1L << i;
            }
        }
        return fired;
    }

    private long all() {
        return transducers >= Long.SIZE ? -1L : (1L << transducers) - 1;
    }
}
