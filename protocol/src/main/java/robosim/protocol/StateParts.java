package robosim.protocol;

import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.StringJoiner;

/**
 * The parts of a robot's state that its sensors and accessories add, by {@link StatePart}, and the
 * one list of the parts there are. Immutable: {@link #with} makes a new one.
 *
 * <p>A new sensor's part is registered by adding its key to {@link #ALL}; the wire then writes it
 * as a field of the state named after the key, and reads it back (see docs/EXTENDING.md).
 */
public final class StateParts {
    /**
     * Every part a state may carry, in the order the wire writes them. The one place a part is
     * registered: a state cannot hold a part missing here.
     */
    public static final List<StatePart<?>> ALL = List.of(
            SonarReading.PART,
            LaserReading.PART,
            HeatReading.PART,
            Bumpers.PART,
            TruePose.PART,
            GripperState.PART,
            CameraView.PART,
            BatteryReading.PART);

    private static final Map<String, Integer> BY_NAME = byName();

    /** A state with no parts: every sensor off, no accessory. */
    public static final StateParts NONE = new StateParts(new Object[ALL.size()]);

    private final Object[] values;

    private StateParts(Object[] values) {
        this.values = values;
    }

    private static Map<String, Integer> byName() {
        Map<String, Integer> m = new HashMap<>();
        for (int i = 0; i < ALL.size(); i++) {
            if (m.put(ALL.get(i).name(), i) != null) {
                throw new IllegalStateException("two state parts are named " + ALL.get(i).name());
            }
        }
        return Map.copyOf(m);
    }

    /**
     * @param name a part's field on the wire
     * @return its key, or null when no registered part has the name
     */
    public static StatePart<?> named(String name) {
        Integer i = BY_NAME.get(name);
        return i == null ? null : ALL.get(i);
    }

    /**
     * @param name a part's field on the wire
     * @return its place in {@link #ALL}, or -1 when no registered part has the name
     */
    static int indexNamed(String name) {
        Integer i = BY_NAME.get(name);
        return i == null ? -1 : i;
    }

    /**
     * @param values each part's value by its place in {@link #ALL}, null for none, each of its part's
     *               type; the array is the parts' own from then on
     * @return the parts
     */
    static StateParts ofValues(Object[] values) {
        if (values.length != ALL.size()) {
            throw new IllegalArgumentException(values.length + " values for " + ALL.size() + " parts");
        }
        for (int i = 0; i < values.length; i++) {
            if (values[i] != null) {
                ALL.get(i).type().cast(values[i]);
            }
        }
        return new StateParts(values);
    }

    private static int index(StatePart<?> part) {
        Integer i = BY_NAME.get(part.name());
        if (i == null || !ALL.get(i).equals(part)) {
            throw new IllegalArgumentException("state part " + part.name() + " is not registered in StateParts.ALL");
        }
        return i;
    }

    /**
     * @param part a part's key
     * @param <T>  its value's type
     * @return the part's value, or null when these parts hold none
     */
    public <T> T get(StatePart<T> part) {
        return part.type().cast(values[index(part)]);
    }

    /**
     * @param part  a part's key
     * @param value its value; null removes it
     * @param <T>   its value's type
     * @return these parts with that one set
     * @throws IllegalArgumentException if the part is not registered in {@link #ALL}
     */
    public <T> StateParts with(StatePart<T> part, T value) {
        int i = index(part);
        if (values[i] == value) {
            return this;
        }
        Object[] copy = values.clone();
        copy[i] = value == null ? null : part.type().cast(value);
        return new StateParts(copy);
    }

    /** @return whether no part is held */
    public boolean isEmpty() {
        for (Object v : values) {
            if (v != null) {
                return false;
            }
        }
        return true;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof StateParts other && Arrays.equals(values, other.values);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(values);
    }

    @Override
    public String toString() {
        StringJoiner j = new StringJoiner(", ", "{", "}");
        for (int i = 0; i < values.length; i++) {
            if (values[i] != null) {
                j.add(ALL.get(i).name() + "=" + values[i]);
            }
        }
        return j.toString();
    }
}
