package robosim.env.sensors;

/**
 * A sensor's own clock (the original RoboSim's {@code PeriodicSensor}): it fires every
 * {@code periodMs} of simulated time, at 0, period, 2·period, ..., whatever the step length, so a
 * step may hold several firings or none. Firings are numbered from 0; the clock says which firings
 * fall in a step, and a sensor decides what each one reads.
 */
final class PeriodicSensor {
    private final long periodMs;

    /**
     * @param periodMs simulated ms between firings, greater than 0
     * @throws IllegalArgumentException if not greater than 0
     */
    PeriodicSensor(long periodMs) {
        if (periodMs <= 0) {
            throw new IllegalArgumentException(periodMs + " was supplied for periodMs: a period is greater than 0");
        }
        this.periodMs = periodMs;
    }

    /**
     * @param afterMs the end of the previous step (exclusive)
     * @param toMs    the end of this step (inclusive)
     * @return the number of the first firing in (afterMs, toMs]
     */
    long firstFiring(long afterMs, long toMs) {
        return Math.floorDiv(afterMs, periodMs) + 1;
    }

    /**
     * @param afterMs the end of the previous step (exclusive)
     * @param toMs    the end of this step (inclusive)
     * @return how many firings fall in (afterMs, toMs]; 0 if {@code toMs} is not after {@code afterMs}
     */
    long firings(long afterMs, long toMs) {
        return toMs <= afterMs ? 0 : Math.floorDiv(toMs, periodMs) - Math.floorDiv(afterMs, periodMs);
    }
}
