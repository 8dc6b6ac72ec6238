package robosim.bench;

import java.util.Locale;
import java.util.Optional;

/** Which sensors every benchmark robot reads each step. */
public enum BenchSensors {
    /** The 16 sonars. */
    SONAR("sonar", "sonar"),
    /** The 16 sonars and a SICK laser: 181 beams at 1°, 8000 mm. */
    LASER("laser", "sonar+laser");

    /** The laser's angle between beams, degrees. */
    public static final double LASER_INCREMENT = 1.0;
    /** The laser's maximum range, mm. */
    public static final int LASER_MAX_RANGE = 8000;

    private final String optionName;
    private final String label;

    BenchSensors(String optionName, String label) {
        this.optionName = optionName;
        this.label = label;
    }

    /** @return the name on the command line: {@code sonar} or {@code laser} */
    public String optionName() {
        return optionName;
    }

    /** @return what the figures call it: {@code sonar} or {@code sonar+laser} */
    public String label() {
        return label;
    }

    /** @return whether the robots switch their laser on and read it */
    public boolean laser() {
        return this == LASER;
    }

    /**
     * @param name {@code sonar} or {@code laser}, in any case
     * @return the sensors it names, or empty if it names none
     */
    public static Optional<BenchSensors> named(String name) {
        String n = name.strip().toLowerCase(Locale.ROOT);
        for (BenchSensors s : values()) {
            if (s.optionName.equals(n)) {
                return Optional.of(s);
            }
        }
        return Optional.empty();
    }
}
