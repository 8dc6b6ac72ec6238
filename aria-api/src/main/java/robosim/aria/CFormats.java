package robosim.aria;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import java.util.Locale;
import java.util.regex.Pattern;

/**
 * C's number formats and number parsing where ARIA's text depends on them and Java's differ: C's
 * {@code %g} strips trailing zeros ({@code 1}, where Java's {@code %g} gives {@code 1.00000}), and
 * {@code strtod} takes {@code inf} but not Java's {@code 1d}.
 */
final class CFormats {
    private static final Pattern DECIMAL = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?");

    private CFormats() {
    }

    /** @return {@code d} as C's {@code printf("%g", d)} writes it */
    static String g(double d) {
        if (Double.isNaN(d)) {
            return "nan";
        }
        if (Double.isInfinite(d)) {
            return d > 0 ? "inf" : "-inf";
        }
        String sign = d < 0 || (d == 0 && 1 / d < 0) ? "-" : "";
        if (d == 0) {
            return sign + "0";
        }
        BigDecimal rounded = new BigDecimal(Math.abs(d)).round(new MathContext(6, RoundingMode.HALF_EVEN));
        int exponent = rounded.precision() - rounded.scale() - 1;
        if (exponent < -4 || exponent >= 6) {
            BigDecimal mantissa = rounded.movePointLeft(exponent);
            return sign + strip(mantissa.setScale(5, RoundingMode.HALF_EVEN).toPlainString())
                    + String.format(Locale.ROOT, "e%s%02d", exponent < 0 ? "-" : "+", Math.abs(exponent));
        }
        return sign + strip(rounded.setScale(5 - exponent, RoundingMode.HALF_EVEN).toPlainString());
    }

    private static String strip(String fixed) {
        if (fixed.indexOf('.') < 0) {
            return fixed;
        }
        String s = fixed.replaceAll("0+$", "");
        return s.endsWith(".") ? s.substring(0, s.length() - 1) : s;
    }

    /** @return {@code d} as C's {@code printf("%.*f", precision, d)} writes it (exact ties to even) */
    static String fixed(double d, int precision) {
        if (Double.isNaN(d) || Double.isInfinite(d)) {
            return g(d);
        }
        String s = new BigDecimal(d).setScale(precision, RoundingMode.HALF_EVEN).toPlainString();
        return (d < 0 || (d == 0 && 1 / d < 0)) && !s.startsWith("-") ? "-" + s : s;
    }

    /**
     * An int as ARIA's {@code ArArgumentBuilder::getArgInt} reads one ({@code strtol}, base 10 or
     * 16 after {@code 0x}, the whole word).
     *
     * @return the value, or null if the word is not one
     */
    static Integer parseInt(String word) {
        if (word == null) {
            return null;
        }
        String digits = word;
        int radix = 10;
        if (word.length() > 2 && word.charAt(0) == '0' && (word.charAt(1) == 'x' || word.charAt(1) == 'X')) {
            digits = word.substring(2);
            radix = 16;
        }
        try {
            long v = Long.parseLong(digits, radix);
            return v >= Integer.MIN_VALUE && v <= Integer.MAX_VALUE ? (int) v : null;
        } catch (NumberFormatException e) {
            return null;
        }
    }

    /**
     * A double as ARIA's {@code ArArgumentBuilder::getArgDouble} reads one ({@code strtod}, the
     * whole word; {@code INF} and {@code -INF} too).
     *
     * @return the value, or null if the word is not one
     */
    static Double parseDouble(String word) {
        if (word == null) {
            return null;
        }
        String w = word.startsWith("+") || word.startsWith("-") ? word.substring(1) : word;
        double sign = word.startsWith("-") ? -1 : 1;
        if (w.equalsIgnoreCase("inf") || w.equalsIgnoreCase("infinity")) {
            return sign * Double.POSITIVE_INFINITY;
        }
        if (w.equalsIgnoreCase("nan")) {
            return Double.NaN;
        }
        return DECIMAL.matcher(word).matches() ? Double.parseDouble(word) : null;
    }

    /** @return true, false, or null as ARIA's {@code ArArgumentBuilder::getArgBool} reads a word */
    static Boolean parseBool(String word) {
        if (word == null) {
            return null;
        }
        if (word.equalsIgnoreCase("true") || word.equals("1")) {
            return true;
        }
        if (word.equalsIgnoreCase("false") || word.equals("0")) {
            return false;
        }
        return null;
    }
}
