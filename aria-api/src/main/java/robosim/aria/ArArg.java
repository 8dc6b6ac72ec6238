package robosim.aria;

import java.util.Locale;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import java.util.function.DoubleConsumer;
import java.util.function.DoubleSupplier;
import java.util.function.IntConsumer;
import java.util.function.IntSupplier;
import java.util.function.Supplier;

/**
 * ARIA's {@code ArArg}: a named parameter of an action (or of anything configurable) that other
 * parts of a program can find, read and set. Where C++ holds a pointer to the variable, Java holds
 * how to read it and how to set it, made by a factory of its kind:
 * <pre>{@code
 * setNextArgument(ArArg.ofDouble("maximum speed", () -> myMaxSpeed, v -> myMaxSpeed = v, "Maximum speed to go."));
 * }</pre>
 */
public final class ArArg {
    /** What kind of value an argument holds (ARIA's {@code ArArg::Type}, the kinds Java carries). */
    public enum Type {
        /** A whole number. */
        INT,
        /** A number. */
        DOUBLE,
        /** A string. */
        STRING,
        /** True or false. */
        BOOL
    }

    private final String name;
    private final String description;
    private final Type type;
    private final Supplier<Object> get;
    private final Consumer<Object> set;

    private ArArg(String name, String description, Type type, Supplier<Object> get, Consumer<Object> set) {
        this.name = name;
        this.description = description == null ? "" : description;
        this.type = type;
        this.get = get;
        this.set = set;
    }

    /**
     * A number argument (ARIA's {@code ArArg(name, double *, description)}).
     *
     * @param name        its name
     * @param get         reads the value
     * @param set         sets it
     * @param description what it is
     * @return the argument
     */
    public static ArArg ofDouble(String name, DoubleSupplier get, DoubleConsumer set, String description) {
        return new ArArg(name, description, Type.DOUBLE, get::getAsDouble, v -> set.accept(((Number) v).doubleValue()));
    }

    /**
     * A whole-number argument (ARIA's {@code ArArg(name, int *, description)}).
     *
     * @param name        its name
     * @param get         reads the value
     * @param set         sets it
     * @param description what it is
     * @return the argument
     */
    public static ArArg ofInt(String name, IntSupplier get, IntConsumer set, String description) {
        return new ArArg(name, description, Type.INT, get::getAsInt, v -> set.accept(((Number) v).intValue()));
    }

    /**
     * A true-or-false argument (ARIA's {@code ArArg(name, bool *, description)}).
     *
     * @param name        its name
     * @param get         reads the value
     * @param set         sets it
     * @param description what it is
     * @return the argument
     */
    public static ArArg ofBool(String name, BooleanSupplier get, Consumer<Boolean> set, String description) {
        return new ArArg(name, description, Type.BOOL, get::getAsBoolean, v -> set.accept((Boolean) v));
    }

    /**
     * A string argument (ARIA's {@code ArArg(name, char *, description, maxLen)}).
     *
     * @param name        its name
     * @param get         reads the value
     * @param set         sets it
     * @param description what it is
     * @return the argument
     */
    public static ArArg ofString(String name, Supplier<String> get, Consumer<String> set, String description) {
        return new ArArg(name, description, Type.STRING, get::get, v -> set.accept((String) v));
    }

    /** @return its name */
    public String getName() {
        return name;
    }

    /** @return what it is */
    public String getDescription() {
        return description;
    }

    /** @return the kind of value it holds */
    public Type getType() {
        return type;
    }

    private void require(Type wanted) {
        if (type != wanted) {
            throw new IllegalStateException("argument '" + name + "' holds a " + type + ", not a " + wanted);
        }
    }

    /** @return its value @throws IllegalStateException if it is not a {@link Type#DOUBLE} */
    public double getDouble() {
        require(Type.DOUBLE);
        return (Double) get.get();
    }

    /** @param value its new value @return true @throws IllegalStateException if it is not a DOUBLE */
    public boolean setDouble(double value) {
        require(Type.DOUBLE);
        set.accept(value);
        return true;
    }

    /** @return its value @throws IllegalStateException if it is not an {@link Type#INT} */
    public int getInt() {
        require(Type.INT);
        return (Integer) get.get();
    }

    /** @param value its new value @return true @throws IllegalStateException if it is not an INT */
    public boolean setInt(int value) {
        require(Type.INT);
        set.accept(value);
        return true;
    }

    /** @return its value @throws IllegalStateException if it is not a {@link Type#BOOL} */
    public boolean getBool() {
        require(Type.BOOL);
        return (Boolean) get.get();
    }

    /** @param value its new value @return true @throws IllegalStateException if it is not a BOOL */
    public boolean setBool(boolean value) {
        require(Type.BOOL);
        set.accept(value);
        return true;
    }

    /** @return its value @throws IllegalStateException if it is not a {@link Type#STRING} */
    public String getString() {
        require(Type.STRING);
        return (String) get.get();
    }

    /** @param value its new value @return true @throws IllegalStateException if it is not a STRING */
    public boolean setString(String value) {
        require(Type.STRING);
        set.accept(value);
        return true;
    }

    /** Logs its name, kind and value, as ARIA's {@code ArArg::log}. */
    public void log() {
        ArLog.log(ArLog.Terse, "\tName: %s", name);
        Object v = get.get();
        ArLog.log(ArLog.Terse, "\tType: %s: %s", type.name().toLowerCase(Locale.ROOT),
                v instanceof Double d ? String.format(Locale.ROOT, "%g", d) : v);
        if (!description.isEmpty()) {
            ArLog.log(ArLog.Terse, "\tDescription: %s", description);
        }
    }
}
