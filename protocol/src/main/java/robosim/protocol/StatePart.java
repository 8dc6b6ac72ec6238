package robosim.protocol;

/**
 * The key of one part of a robot's state: what one sensor or accessory adds to it, such as the
 * sonar ring's ranges or the battery's voltage. A part's record declares its key as a constant
 * ({@code SonarReading.PART}), and {@link StateParts#ALL} registers it, which is what lets the wire
 * carry it; a {@link RobotState} then holds the part's value, or none.
 *
 * @param name   the part's field in the state as the wire writes it: lower camel case, unique
 * @param type   the class of its value
 * @param absent what {@link RobotState#get(StatePart)} gives when the state holds none: a value
 *               that reads as "off" (an empty sonar reading), or null
 * @param <T>    the type of its value
 */
public record StatePart<T>(String name, Class<T> type, T absent) {
    /** Checks the name and the type. */
    public StatePart {
        if (name == null || !name.matches("[a-z][A-Za-z0-9]{0,31}")) {
            throw new IllegalArgumentException("'" + name + "' was supplied for a state part's name: lower camel case,"
                    + " at most 32 letters and digits");
        }
        if (type == null) {
            throw new IllegalArgumentException("state part " + name + " needs the class of its value");
        }
    }

    /**
     * A part that reads as null when absent.
     *
     * @param name the part's field on the wire
     * @param type the class of its value
     * @param <T>  the type of its value
     * @return the key
     */
    public static <T> StatePart<T> of(String name, Class<T> type) {
        return new StatePart<>(name, type, null);
    }
}
