package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.annotation.JsonSetter;
import com.fasterxml.jackson.annotation.Nulls;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.regex.Pattern;

/**
 * The Environment's answer to a {@link RobotHello}: the robot is in the world.
 *
 * <p>A welcome without {@code properties} or {@code seed}, as peers older than these fields send
 * it, reads as one with no properties and seed 0.
 *
 * @param name       the robot's name
 * @param stepMs     the length of one time step in simulated milliseconds
 * @param state      the robot's state before the first step
 * @param properties the world's properties (its {@code <property>} elements), in file order: what a
 *                   robot program needs to know of the world, such as a maze's cell size; at most
 *                   {@value #MAX_PROPERTIES}, each name following {@link #PROPERTY_NAME_RULE} and each
 *                   value at most {@value #MAX_PROPERTY_VALUE} characters
 * @param seed       the run's seed, so that a robot's own random choices can follow it and a run
 *                   stays repeatable; 0 when there is no run (a robot on a Pioneer port)
 */
public record Welcome(String name, int stepMs, RobotState state,
                      @JsonInclude(JsonInclude.Include.NON_EMPTY) Map<String, String> properties,
                      @JsonSetter(nulls = Nulls.AS_EMPTY) long seed) implements Message {
    /** The most properties a world may give its robots. */
    public static final int MAX_PROPERTIES = 256;
    /** The longest value of a property, in characters. */
    public static final int MAX_PROPERTY_VALUE = 1024;
    /** What a property's name may be: a letter, then up to 63 letters, digits, '.', '_' or '-'. */
    public static final Pattern PROPERTY_NAME = Pattern.compile("[A-Za-z][A-Za-z0-9._-]{0,63}");
    /** The rule of {@link #PROPERTY_NAME}, in words. */
    public static final String PROPERTY_NAME_RULE =
            "a property's name is a letter (A-Z, a-z) then up to 63 letters, digits, '.', '_' or '-'";

    /**
     * Copies the properties, keeping their order, so the record stays immutable, and checks them.
     *
     * @throws IllegalArgumentException if there are more than {@value #MAX_PROPERTIES} properties,
     *                                  or a name or value breaks its rule (the message names it)
     */
    public Welcome {
        if (properties == null) {
            properties = Map.of();
        }
        if (properties.size() > MAX_PROPERTIES) {
            throw new IllegalArgumentException("a welcome carries at most " + MAX_PROPERTIES + " world properties, got "
                    + properties.size());
        }
        Map<String, String> copy = new LinkedHashMap<>();
        for (Map.Entry<String, String> p : properties.entrySet()) {
            String v = propertyViolation(p.getKey(), p.getValue());
            if (v != null) {
                throw new IllegalArgumentException(v);
            }
            copy.put(p.getKey(), p.getValue());
        }
        properties = Collections.unmodifiableMap(copy);
    }

    /**
     * A welcome to a world without properties, outside a run (seed 0).
     *
     * @param name   the robot's name
     * @param stepMs the length of one time step in simulated milliseconds
     * @param state  the robot's state before the first step
     */
    public Welcome(String name, int stepMs, RobotState state) {
        this(name, stepMs, state, Map.of(), 0);
    }

    /**
     * Checks one property of a world, as a world file and the wire give it.
     *
     * @param name  the property's name
     * @param value its value
     * @return the broken rule, naming the value, or null if the property is sound
     */
    public static String propertyViolation(String name, String value) {
        if (name == null || !PROPERTY_NAME.matcher(name).matches()) {
            return RobotHello.quoted(name) + " was supplied for a property's name: " + PROPERTY_NAME_RULE;
        }
        if (value == null) {
            return "property " + name + " has no value: a property's value is text, possibly empty";
        }
        if (value.length() > MAX_PROPERTY_VALUE) {
            return "property " + name + " has a value of " + value.length() + " characters: a property's value is at most "
                    + MAX_PROPERTY_VALUE + " characters";
        }
        return null;
    }
}
