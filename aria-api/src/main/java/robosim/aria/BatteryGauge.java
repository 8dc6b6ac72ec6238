package robosim.aria;

import robosim.protocol.BatteryReading;

/**
 * What {@link ArRobot} knows of its battery, as ARIA's {@code ArRobot} keeps it: the latest
 * reading, and the running average of the latest {@value #DEFAULT_AVERAGE_OF} readings (ARIA's
 * {@code ArRunningAverage}), which starts from ARIA's 13 V before the first reading. A robot's
 * battery is a 12 V pack, so the voltage normalised to 12 V and the real voltage are the same.
 */
final class BatteryGauge {
    /** How many readings the average is of, as ARIA's default. */
    static final int DEFAULT_AVERAGE_OF = 20;
    /** What ARIA reads before the first reading, V. */
    static final double BEFORE_FIRST_READING = 13;

    private final Average average = new Average();
    private final Average realAverage = new Average();
    private double now = BEFORE_FIRST_READING;
    private double stateOfCharge;
    private boolean haveStateOfCharge;

    private boolean ignoreReadings;
    private long stateOfChargeSetMs;
    private double realNow = BEFORE_FIRST_READING;

    /**
     * @param b      a state's battery reading; null (a robot server that does not say) changes nothing,
     *               nor does any while {@link #setIgnoreReadings} holds
     * @param timeMs the state's simulated time
     */
    void update(BatteryReading b, long timeMs) {
        if (b == null || ignoreReadings) {
            return;
        }
        now = b.volts();
        realNow = now;
        average.add(now);
        realAverage.add(now);
        stateOfCharge = b.stateOfCharge();
        haveStateOfCharge |= stateOfCharge > 0; // as ARIA: a charge of 0 is a robot that does not report one
        if (stateOfCharge > 0) {
            stateOfChargeSetMs = timeMs;
        }
    }

    /** ARIA's {@code setStateOfCharge}: the robot has one from now on. */
    void setStateOfCharge(double soc, long timeMs) {
        haveStateOfCharge = true;
        stateOfCharge = soc;
        stateOfChargeSetMs = timeMs;
    }

    long stateOfChargeSetMs() {
        return stateOfChargeSetMs;
    }

    void setIgnoreReadings(boolean ignore) {
        ignoreReadings = ignore;
    }

    /** ARIA's {@code setBatteryInfo}: an external battery's reading. */
    void setInfo(double real, double normalized, boolean haveSoc, double soc, long timeMs) {
        realNow = real;
        realAverage.add(real);
        now = normalized;
        average.add(normalized);
        if (haveSoc) {
            setStateOfCharge(soc, timeMs);
        }
    }

    double realVoltageNow() {
        return realNow;
    }

    double voltage() {
        return average.value();
    }

    double voltageNow() {
        return now;
    }

    double realVoltage() {
        return realAverage.value();
    }

    boolean haveStateOfCharge() {
        return haveStateOfCharge;
    }

    double stateOfCharge() {
        return haveStateOfCharge ? stateOfCharge : 0;
    }

    int averageOf() {
        return average.of;
    }

    void setAverageOf(int n) {
        average.setOf(n);
    }

    int realAverageOf() {
        return realAverage.of;
    }

    void setRealAverageOf(int n) {
        realAverage.setOf(n);
    }

    /** ARIA's {@code ArRunningAverage}: the mean of the latest {@code of} values. */
    private static final class Average {
        /** The readings kept, oldest first from {@link #first}, in a ring that grows when the count is raised. */
        private double[] values = new double[DEFAULT_AVERAGE_OF + 1];
        private int first;
        private int size;
        private double sum;
        private int of = DEFAULT_AVERAGE_OF;

        Average() {
            add(BEFORE_FIRST_READING);
        }

        void add(double v) {
            if (size == values.length) {
                grow();
            }
            values[(first + size) % values.length] = v;
            size++;
            sum += v;
            trim();
        }

        void setOf(int n) {
            if (n < 1) {
                throw new IllegalArgumentException(n + " was supplied for the readings to average: at least 1");
            }
            of = n;
            trim();
        }

        private void grow() {
            double[] more = new double[values.length * 2];
            for (int i = 0; i < size; i++) {
                more[i] = values[(first + i) % values.length];
            }
            values = more;
            first = 0;
        }

        private void trim() {
            while (size > of) {
                sum -= values[first];
                first = (first + 1) % values.length;
                size--;
            }
        }

        double value() {
            return sum / size;
        }
    }
}
