package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonInclude;

/**
 * The sonar ring's part of a robot's state, while its sonars are on.
 *
 * @param ranges the range of each transducer, mm, by index
 * @param fresh  which readings are new in this state when the ring fires in sequence
 *               ({@link Command.SetSonarCycle}): bit i set when transducer i fired; null when every
 *               transducer fired
 */
public record SonarReading(int[] ranges, @JsonInclude(JsonInclude.Include.NON_NULL) Long fresh) {
    /** The reading of a ring that is off: no ranges. */
    public static final SonarReading OFF = new SonarReading(new int[0], null);

    /** Its key: absent reads as {@link #OFF}. */
    public static final StatePart<SonarReading> PART = new StatePart<>("sonar", SonarReading.class, OFF);

    /** Checks the ranges are there. */
    public SonarReading {
        if (ranges == null) {
            throw new IllegalArgumentException("a sonar reading needs its ranges");
        }
    }

    /**
     * @param ranges every transducer's range, all fresh
     */
    public SonarReading(int[] ranges) {
        this(ranges, null);
    }

    /**
     * @param i a transducer's index
     * @return whether its reading is new in this state ({@link #fresh()} null means all are)
     */
    public boolean isNew(int i) {
        return fresh == null || i >= 0 && i < Long.SIZE && (fresh >> i & 1) != 0;
    }
}
