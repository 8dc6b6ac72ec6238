package robosim.aria;

import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import java.util.function.DoubleConsumer;
import java.util.function.DoubleSupplier;
import java.util.function.IntConsumer;
import java.util.function.IntSupplier;
import java.util.function.Supplier;

/**
 * ARIA's {@code ArConfigArg}: one parameter of an {@link ArConfig}, with its name, description,
 * type, bounds and priority. Where C++ gives a pointer to the program's variable ({@code
 * ArConfigArg("Speed", &mySpeed, "Speed to go.", 0, 1000)}), Java gives how to read it and how to
 * set it, through the factory of its type:
 * <pre>{@code
 * config.addParam(ArConfigArg.ofInt("Speed", () -> mySpeed, v -> mySpeed = v, "Speed to go.", 0, 1000),
 *         "Motion", ArPriority.NORMAL);
 * }</pre>
 * The constructors make an argument that holds its own value (C++'s {@code ArConfigArg(name, int
 * val, ...)}), a comment ({@link Type#DESCRIPTION_HOLDER}) or a saved unknown parameter ({@link
 * Type#STRING_HOLDER}). The setters check the bounds and, as ARIA's, put the reason in an error
 * buffer (a {@link StringBuilder}) when one is given. Follows ARIA's {@code ArConfigArg.h} and
 * {@code ArConfigArg.cpp}; ARIA's list, functor and {@code std::string} kinds are left out.
 */
public final class ArConfigArg {
    /** The kinds of parameter (ARIA's {@code ArConfigArg::Type}, the ones RoboSim carries). */
    public enum Type {
        /** An argument made with no value. */
        INVALID,
        /** A whole number with bounds. */
        INT,
        /** A number with bounds and a precision for writing. */
        DOUBLE,
        /** A string, with a maximum length when bound to the program's. */
        STRING,
        /** True or false. */
        BOOL,
        /** A comment only. */
        DESCRIPTION_HOLDER,
        /** A parameter read from a file that nobody added: its name and text, kept to be written back. */
        STRING_HOLDER,
        /** An empty entry that separates others in a large section. */
        SEPARATOR
    }

    /** The digits after the point a {@link Type#DOUBLE} is written with unless told (ARIA's 5). */
    public static final int DEFAULT_DOUBLE_PRECISION = 5;

    private final Type type;
    private String name;
    private String description;
    private final Supplier<Object> get;
    private final Consumer<Object> set;
    private final int minInt;
    private final int maxInt;
    private final double minDouble;
    private final double maxDouble;
    private final int precision;
    private final int maxStrLen;
    private ArPriority priority = ArPriority.NORMAL;
    private String displayHint = "";
    private boolean ignoreBounds;

    private ArConfigArg(Type type, String name, String description, Supplier<Object> get, Consumer<Object> set,
            int[] intBounds, double[] doubleBounds, int precision, int maxStrLen) {
        this.type = type;
        this.name = name == null ? "" : name;
        this.description = description == null ? "" : description;
        this.get = get;
        this.set = set;
        this.minInt = intBounds[0];
        this.maxInt = intBounds[1];
        this.minDouble = doubleBounds[0];
        this.maxDouble = doubleBounds[1];
        this.precision = precision;
        this.maxStrLen = maxStrLen;
    }

    private static final int[] NO_INT_BOUNDS = {Integer.MIN_VALUE, Integer.MAX_VALUE};
    private static final double[] NO_DOUBLE_BOUNDS = {Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY};

    private static ArConfigArg owned(Type type, String name, String description, Object value, int[] intBounds,
            double[] doubleBounds, int precision) {
        Object[] box = {value};
        return new ArConfigArg(type, name, description, () -> box[0], v -> box[0] = v, intBounds, doubleBounds,
                precision, 0);
    }

    private ArConfigArg(ArConfigArg a) {
        this(a.type, a.name, a.description, a.get, a.set, new int[] {a.minInt, a.maxInt},
                new double[] {a.minDouble, a.maxDouble}, a.precision, a.maxStrLen);
        priority = a.priority;
        displayHint = a.displayHint;
        ignoreBounds = a.ignoreBounds;
    }

    /** An argument of no kind ({@link Type#INVALID}), as ARIA's default constructor makes. */
    public ArConfigArg() {
        this(Type.INVALID, "", "", () -> null, v -> { }, NO_INT_BOUNDS, NO_DOUBLE_BOUNDS, 0, 0);
    }

    /**
     * A comment, or an argument of a kind with no value ({@link Type#SEPARATOR}).
     *
     * @param str  the comment
     * @param type {@link Type#DESCRIPTION_HOLDER} or {@link Type#SEPARATOR}
     */
    public ArConfigArg(String str, Type type) {
        this(type, "", str, () -> null, v -> { }, NO_INT_BOUNDS, NO_DOUBLE_BOUNDS, 0, 0);
    }

    /** @param comment a comment line of its section ({@link Type#DESCRIPTION_HOLDER}) */
    public ArConfigArg(String comment) {
        this(comment, Type.DESCRIPTION_HOLDER);
    }

    /** @param type an argument of a kind with no value, such as {@link Type#SEPARATOR} */
    public ArConfigArg(Type type) {
        this("", type);
    }

    /**
     * A parameter read from a file that nobody added ({@link Type#STRING_HOLDER}): ARIA's {@code
     * ArConfigArg(name, str)}.
     *
     * @param name its name
     * @param str  its text
     */
    public ArConfigArg(String name, String str) {
        this(owned(Type.STRING_HOLDER, name, "", str == null ? "" : str, NO_INT_BOUNDS, NO_DOUBLE_BOUNDS, 0));
    }

    /**
     * A string that the argument holds itself, of any length.
     *
     * @param name        its name
     * @param str         its first value
     * @param description what it is
     */
    public ArConfigArg(String name, String str, String description) {
        this(owned(Type.STRING, name, description, str == null ? "" : str, NO_INT_BOUNDS, NO_DOUBLE_BOUNDS, 0));
    }

    /**
     * A whole number that the argument holds itself, within bounds.
     *
     * @param name        its name
     * @param val         its first value
     * @param description what it is
     * @param minInt      the least value ({@link Integer#MIN_VALUE}: none)
     * @param maxInt      the greatest value ({@link Integer#MAX_VALUE}: none)
     */
    public ArConfigArg(String name, int val, String description, int minInt, int maxInt) {
        this(owned(Type.INT, name, description, val, new int[] {minInt, maxInt}, NO_DOUBLE_BOUNDS, 0));
    }

    /** @param name its name @param val its first value @param description what it is (no bounds) */
    public ArConfigArg(String name, int val, String description) {
        this(name, val, description, Integer.MIN_VALUE, Integer.MAX_VALUE);
    }

    /**
     * A number that the argument holds itself, within bounds.
     *
     * @param name        its name
     * @param val         its first value
     * @param description what it is
     * @param minDouble   the least value (negative infinity: none)
     * @param maxDouble   the greatest value (infinity: none)
     * @param precision   the digits after the point when written (negative: C's {@code %g})
     */
    public ArConfigArg(String name, double val, String description, double minDouble, double maxDouble, int precision) {
        this(owned(Type.DOUBLE, name, description, val, NO_INT_BOUNDS, new double[] {minDouble, maxDouble}, precision));
    }

    /** @param name its name @param val its first value @param description what it is (no bounds) */
    public ArConfigArg(String name, double val, String description) {
        this(name, val, description, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY, DEFAULT_DOUBLE_PRECISION);
    }

    /** @param name its name @param val its first value @param description what it is */
    public ArConfigArg(String name, boolean val, String description) {
        this(owned(Type.BOOL, name, description, val, NO_INT_BOUNDS, NO_DOUBLE_BOUNDS, 0));
    }

    /**
     * The program's whole number, within bounds: ARIA's {@code ArConfigArg(name, int *pointer,
     * description, minInt, maxInt)}.
     *
     * @param name        its name
     * @param get         reads the program's value
     * @param set         sets it
     * @param description what it is
     * @param minInt      the least value ({@link Integer#MIN_VALUE}: none)
     * @param maxInt      the greatest value ({@link Integer#MAX_VALUE}: none)
     * @return the argument
     */
    public static ArConfigArg ofInt(String name, IntSupplier get, IntConsumer set, String description, int minInt,
            int maxInt) {
        return new ArConfigArg(Type.INT, name, description, get::getAsInt, v -> set.accept((Integer) v),
                new int[] {minInt, maxInt}, NO_DOUBLE_BOUNDS, 0, 0);
    }

    /** @param name its name @param get reads it @param set sets it @param description what it is @return the argument, unbounded */
    public static ArConfigArg ofInt(String name, IntSupplier get, IntConsumer set, String description) {
        return ofInt(name, get, set, description, Integer.MIN_VALUE, Integer.MAX_VALUE);
    }

    /**
     * The program's number, within bounds: ARIA's {@code ArConfigArg(name, double *pointer,
     * description, minDouble, maxDouble, precision)}.
     *
     * @param name        its name
     * @param get         reads the program's value
     * @param set         sets it
     * @param description what it is
     * @param minDouble   the least value (negative infinity: none)
     * @param maxDouble   the greatest value (infinity: none)
     * @param precision   the digits after the point when written (negative: C's {@code %g})
     * @return the argument
     */
    public static ArConfigArg ofDouble(String name, DoubleSupplier get, DoubleConsumer set, String description,
            double minDouble, double maxDouble, int precision) {
        return new ArConfigArg(Type.DOUBLE, name, description, get::getAsDouble, v -> set.accept((Double) v),
                NO_INT_BOUNDS, new double[] {minDouble, maxDouble}, precision, 0);
    }

    /**
     * The program's number within bounds, written with {@link #DEFAULT_DOUBLE_PRECISION} digits.
     *
     * @param name        its name
     * @param get         reads the program's value
     * @param set         sets it
     * @param description what it is
     * @param minDouble   the least value (negative infinity: none)
     * @param maxDouble   the greatest value (infinity: none)
     * @return the argument
     */
    public static ArConfigArg ofDouble(String name, DoubleSupplier get, DoubleConsumer set, String description,
            double minDouble, double maxDouble) {
        return ofDouble(name, get, set, description, minDouble, maxDouble, DEFAULT_DOUBLE_PRECISION);
    }

    /** @param name its name @param get reads it @param set sets it @param description what it is @return the argument, unbounded */
    public static ArConfigArg ofDouble(String name, DoubleSupplier get, DoubleConsumer set, String description) {
        return ofDouble(name, get, set, description, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);
    }

    /**
     * The program's true-or-false: ARIA's {@code ArConfigArg(name, bool *pointer, description)}.
     *
     * @param name        its name
     * @param get         reads the program's value
     * @param set         sets it
     * @param description what it is
     * @return the argument
     */
    public static ArConfigArg ofBool(String name, BooleanSupplier get, Consumer<Boolean> set, String description) {
        return new ArConfigArg(Type.BOOL, name, description, get::getAsBoolean, v -> set.accept((Boolean) v),
                NO_INT_BOUNDS, NO_DOUBLE_BOUNDS, 0, 0);
    }

    /**
     * The program's string of at most {@code maxStrLen - 1} characters, as C's {@code char
     * buffer[maxStrLen]}: ARIA's {@code ArConfigArg(name, char *str, description, maxStrLen)}.
     *
     * @param name        its name
     * @param get         reads the program's value
     * @param set         sets it
     * @param description what it is
     * @param maxStrLen   the buffer's size (0: any length)
     * @return the argument
     */
    public static ArConfigArg ofString(String name, Supplier<String> get, Consumer<String> set, String description,
            int maxStrLen) {
        if (maxStrLen < 0) {
            throw new IllegalArgumentException(maxStrLen + " was supplied for maxStrLen of '" + name
                    + "': maxStrLen must be 0 (any length) or more");
        }
        return new ArConfigArg(Type.STRING, name, description, get::get, v -> set.accept((String) v), NO_INT_BOUNDS,
                NO_DOUBLE_BOUNDS, 0, maxStrLen);
    }

    /** @return a copy sharing the value, as {@link ArConfig#addParam} keeps (ARIA copies the argument) */
    ArConfigArg copy() {
        return new ArConfigArg(this);
    }

    /** @param t a kind @return its name, as ARIA's {@code ArConfigArg::toString(Type)} */
    public static String toString(Type t) {
        return t == null ? "Unknown" : t.name();
    }

    /** @return its kind */
    public Type getType() {
        return type;
    }

    /** @return its name */
    public String getName() {
        return name;
    }

    /** @return what it is ("" if nothing was said) */
    public String getDescription() {
        return description;
    }

    /** @param description what it is, from now on */
    public void setDescription(String description) {
        this.description = description == null ? "" : description;
    }

    /** ARIA's {@code replaceSpacesInName}: white space in the name becomes '_' (done by {@link ArConfig#addParam}). */
    public void replaceSpacesInName() {
        name = name.replaceAll("[ \\t\\n\\x0B\\f\\r]", "_");
    }

    /** @return its priority ({@link ArPriority#NORMAL} unless set) */
    public ArPriority getConfigPriority() {
        return priority;
    }

    /** @param priority its priority, as {@link ArConfig#addParam} sets it */
    public void setConfigPriority(ArPriority priority) {
        this.priority = priority == null ? ArPriority.NORMAL : priority;
    }

    /** @return the hint for an editor's control ("" unless set) */
    public String getDisplayHint() {
        return displayHint;
    }

    /** @param hint the hint for an editor's control, as ARIA's {@code setDisplayHint} */
    public void setDisplayHint(String hint) {
        displayHint = hint == null ? "" : hint;
    }

    /** @param ignoreBounds whether the setters skip the bounds (ARIA: for debugging) */
    public void setIgnoreBounds(boolean ignoreBounds) {
        this.ignoreBounds = ignoreBounds;
    }

    /** @return whether it is a saved unknown parameter ({@link Type#STRING_HOLDER}) */
    public boolean isPlaceholder() {
        return type == Type.STRING_HOLDER;
    }

    /** @return its value if an {@link Type#INT}, else 0 */
    public int getInt() {
        return type == Type.INT ? (Integer) get.get() : 0;
    }

    /** @return its least value if an {@link Type#INT} ({@link Integer#MIN_VALUE}: none) */
    public int getMinInt() {
        return type == Type.INT ? minInt : Integer.MIN_VALUE;
    }

    /** @return its greatest value if an {@link Type#INT} ({@link Integer#MAX_VALUE}: none) */
    public int getMaxInt() {
        return type == Type.INT ? maxInt : Integer.MAX_VALUE;
    }

    /** @return its value if a {@link Type#DOUBLE}, else 0 */
    public double getDouble() {
        return type == Type.DOUBLE ? (Double) get.get() : 0;
    }

    /** @return its least value if a {@link Type#DOUBLE} (negative infinity: none) */
    public double getMinDouble() {
        return type == Type.DOUBLE ? minDouble : Double.NEGATIVE_INFINITY;
    }

    /** @return its greatest value if a {@link Type#DOUBLE} (infinity: none) */
    public double getMaxDouble() {
        return type == Type.DOUBLE ? maxDouble : Double.POSITIVE_INFINITY;
    }

    /** @return the digits after the point it is written with, if a {@link Type#DOUBLE}, else 0 */
    public int getDoublePrecision() {
        return type == Type.DOUBLE ? precision : 0;
    }

    /** @return its value if a {@link Type#BOOL}, else false */
    public boolean getBool() {
        return type == Type.BOOL && (Boolean) get.get();
    }

    /** @return its text if a {@link Type#STRING} or {@link Type#STRING_HOLDER}, else null (as ARIA) */
    public String getString() {
        if (type != Type.STRING && type != Type.STRING_HOLDER) {
            return null;
        }
        Object v = get.get();
        return v == null ? "" : (String) v;
    }

    /** @return the maximum length a bound {@link Type#STRING} takes, plus one (0: any) */
    public int getMaxStrLen() {
        return maxStrLen;
    }

    /** @return whether an {@link Type#INT} or {@link Type#DOUBLE} has a least value */
    public boolean hasMinBound() {
        return type == Type.INT ? minInt != Integer.MIN_VALUE
                : type == Type.DOUBLE && minDouble != Double.NEGATIVE_INFINITY;
    }

    /** @return whether an {@link Type#INT} or {@link Type#DOUBLE} has a greatest value */
    public boolean hasMaxBound() {
        return type == Type.INT ? maxInt != Integer.MAX_VALUE
                : type == Type.DOUBLE && maxDouble != Double.POSITIVE_INFINITY;
    }

    /**
     * @return the bounds as ARIA writes them in a file's comment ({@code range [-10, 10]}, {@code
     *         minimum 0}, {@code maximum 1}), or "": ARIA's {@code getBoundsDescr}
     */
    public String getBoundsDescr() {
        boolean isInt = type == Type.INT;
        if (!isInt && type != Type.DOUBLE) {
            return "";
        }
        String min = isInt ? Integer.toString(minInt) : CFormats.g(minDouble);
        String max = isInt ? Integer.toString(maxInt) : CFormats.g(maxDouble);
        if (hasMinBound()) {
            return hasMaxBound() ? "range [" + min + ", " + max + "]" : "minimum " + min;
        }
        return hasMaxBound() ? "maximum " + max : "";
    }

    /** @param val its new value @return false (logged) if it is out of bounds or not an INT */
    public boolean setInt(int val) {
        return setInt(val, null, 0, false);
    }

    /**
     * ARIA's {@code setInt}.
     *
     * @param val            its new value
     * @param errorBuffer    if not null, given the reason it was refused
     * @param errorBufferLen the buffer's size as C's (0: any); the reason is cut to one less
     * @param doNotSet       check only
     * @return false (logged) if it is not an {@link Type#INT} or the value is out of its bounds
     */
    public boolean setInt(int val, StringBuilder errorBuffer, int errorBufferLen, boolean doNotSet) {
        if (type != Type.INT) {
            ArLog.log(ArLog.Normal, "ArConfigArg::setInt() cannot set %s to %d, wrong type (%s)", name, val, type);
            return false;
        }
        if (!ignoreBounds && val < minInt) {
            ArLog.log(ArLog.Normal, "ArConfigArg of %s: setInt value %d below range [%d, %d]", name, val, minInt, maxInt);
            return error(errorBuffer, errorBufferLen, name + " value of " + val + " is below minimum of " + minInt + ".");
        }
        if (!ignoreBounds && val > maxInt) {
            ArLog.log(ArLog.Normal, "ArConfigArg of %s: setInt value %d above range [%d, %d]", name, val, minInt, maxInt);
            return error(errorBuffer, errorBufferLen, name + " value of " + val + " is above maximum of " + maxInt + ".");
        }
        if (!doNotSet) {
            set.accept(val);
        }
        return true;
    }

    /** @param val its new value @return false (logged) if it is out of bounds or not a DOUBLE */
    public boolean setDouble(double val) {
        return setDouble(val, null, 0, false);
    }

    /**
     * ARIA's {@code setDouble}.
     *
     * @param val            its new value
     * @param errorBuffer    if not null, given the reason it was refused
     * @param errorBufferLen the buffer's size as C's (0: any)
     * @param doNotSet       check only
     * @return false (logged) if it is not a {@link Type#DOUBLE} or the value is out of its bounds
     */
    public boolean setDouble(double val, StringBuilder errorBuffer, int errorBufferLen, boolean doNotSet) {
        String v = CFormats.g(val);
        if (type != Type.DOUBLE) {
            ArLog.log(ArLog.Normal, "ArConfigArg::setDouble() cannot set %s to %s, wrong type (%s)", name, v, type);
            return false;
        }
        String min = CFormats.g(minDouble);
        String max = CFormats.g(maxDouble);
        if (!ignoreBounds && val < minDouble) {
            ArLog.log(ArLog.Normal, "ArConfigArg of %s: setDouble value %s below range [%s, %s]", name, v, min, max);
            return error(errorBuffer, errorBufferLen, name + " value of " + v + " is below minimum of " + min + ".");
        }
        if (!ignoreBounds && val > maxDouble) {
            ArLog.log(ArLog.Normal, "ArConfigArg of %s: setDouble value %s above range [%s, %s]", name, v, min, max);
            return error(errorBuffer, errorBufferLen, name + " value of " + v + " is above maximum of " + max + ".");
        }
        if (!doNotSet) {
            set.accept(val);
        }
        return true;
    }

    /** @param val its new value @return false (logged) if it is not a BOOL */
    public boolean setBool(boolean val) {
        if (type != Type.BOOL) {
            ArLog.log(ArLog.Normal, "ArConfigArg::setBool() cannot set %s to %d, wrong type (%s)", name, val ? 1 : 0,
                    type);
            return false;
        }
        set.accept(val);
        return true;
    }

    /** @param str its new text @return false (logged) if too long or not a STRING */
    public boolean setString(String str) {
        return setString(str, null, 0, false);
    }

    /**
     * ARIA's {@code setString}.
     *
     * @param str            its new text
     * @param errorBuffer    if not null, given the reason it was refused
     * @param errorBufferLen the buffer's size as C's (0: any)
     * @param doNotSet       check only
     * @return false (logged) if it is not a {@link Type#STRING} (or {@link Type#STRING_HOLDER}) or the
     *         text is too long
     */
    public boolean setString(String str, StringBuilder errorBuffer, int errorBufferLen, boolean doNotSet) {
        String s = str == null ? "" : str;
        if (type != Type.STRING && type != Type.STRING_HOLDER) {
            ArLog.log(ArLog.Normal, "ArConfigArg::setString() cannot set %s to %s, wrong type (%s)", name, s, type);
            return false;
        }
        if (maxStrLen > 0 && s.length() >= maxStrLen) {
            ArLog.log(ArLog.Normal, "ArConfigArg of %s: setString called with argument %d long, when max length is %d.",
                    name, s.length(), maxStrLen);
            return error(errorBuffer, errorBufferLen,
                    name + " string is " + s.length() + " long when max length is " + maxStrLen + ".");
        }
        if (!doNotSet) {
            set.accept(s);
        }
        return true;
    }

    private static boolean error(StringBuilder errorBuffer, int errorBufferLen, String reason) {
        ConfigText.putError(errorBuffer, errorBufferLen, reason);
        return false;
    }
}
