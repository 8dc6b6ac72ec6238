package robosim.aria;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Collection;
import java.util.logging.Logger;
import robosim.hw.AbstractRobot;

/**
 * ARIA's utilities that robot programs use ({@code ArUtil}, ariaUtil.h and ariaUtil.cpp in AriaCoda):
 * sleeping and the time (both simulated), string helpers with ARIA's rules for null and for case,
 * number parsing with ARIA's answers for bad input, file-name helpers, unit conversions. C's
 * out-parameters become return values ({@code stripQuotes(String)} returns the stripped string) or
 * one-element arrays ({@code atoi(str, ok, forceHex)}); buffer lengths, which Java strings do not
 * need, are dropped. Calls RoboSim leaves out are listed in docs/ARIA-SEMANTICS.md ("Utility calls
 * RoboSim leaves out").
 */
public final class ArUtil {
    private static final Logger LOG = Logger.getLogger(ArUtil.class.getName());

    /** ARIA's {@code ArUtil::BIT0}: the value with bit 0 set. */
    public static final int BIT0 = 0x1;
    /** ARIA's {@code BIT1}. */
    public static final int BIT1 = 0x2;
    /** ARIA's {@code BIT2}. */
    public static final int BIT2 = 0x4;
    /** ARIA's {@code BIT3}. */
    public static final int BIT3 = 0x8;
    /** ARIA's {@code BIT4}. */
    public static final int BIT4 = 0x10;
    /** ARIA's {@code BIT5}. */
    public static final int BIT5 = 0x20;
    /** ARIA's {@code BIT6}. */
    public static final int BIT6 = 0x40;
    /** ARIA's {@code BIT7}. */
    public static final int BIT7 = 0x80;
    /** ARIA's {@code BIT8}. */
    public static final int BIT8 = 0x100;
    /** ARIA's {@code BIT9}. */
    public static final int BIT9 = 0x200;
    /** ARIA's {@code BIT10}. */
    public static final int BIT10 = 0x400;
    /** ARIA's {@code BIT11}. */
    public static final int BIT11 = 0x800;
    /** ARIA's {@code BIT12}. */
    public static final int BIT12 = 0x1000;
    /** ARIA's {@code BIT13}. */
    public static final int BIT13 = 0x2000;
    /** ARIA's {@code BIT14}. */
    public static final int BIT14 = 0x4000;
    /** ARIA's {@code BIT15}: the value with bit 15 set. */
    public static final int BIT15 = 0x8000;

    /** ARIA's {@code ArUtil::TRUESTRING}. */
    public static final String TRUESTRING = "true";
    /** ARIA's {@code ArUtil::FALSESTRING}. */
    public static final String FALSESTRING = "false";

    private ArUtil() {
    }

    /**
     * Sleeps in simulated time: the calling robot thread yields for {@code ms} simulated
     * milliseconds, rounded up to whole steps, at least one. A thread that belongs to no robot
     * sleeps in wall-clock time. Sleeping while holding the robot's lock is an error: the robot's
     * cycle needs the lock to deliver the next step.
     *
     * @param ms milliseconds
     */
    public static void sleep(long ms) {
        AbstractRobot robot = AbstractRobot.current();
        if (robot != null && robot.isConnected()) {
            robot.sleepSimulated(ms);
            return;
        }
        LOG.fine("ArUtil.sleep outside a robot's code: sleeping in wall-clock time");
        try {
            Thread.sleep(Math.max(0, ms));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * As ARIA's {@code ArUtil::getTime} (ariaUtil.cpp), in simulated time: milliseconds from an
     * arbitrary start (here the start of the run), for comparing with each other within one run.
     * ARIA's is an unsigned int of the monotonic clock; this is the time {@link ArTime} reads.
     *
     * @return simulated ms
     */
    public static long getTime() {
        return SimulatedClock.nowMs();
    }

    // ---- smaller and larger (ARIA deprecates them for std::min and std::max) ----

    /** @param first a value @param second another @return the smaller, as ARIA's {@code findMin} (the second on a tie) */
    public static int findMin(int first, int second) {
        return first < second ? first : second;
    }

    /** @param first a value @param second another @return the larger, as ARIA's {@code findMax} (the second on a tie) */
    public static int findMax(int first, int second) {
        return first > second ? first : second;
    }

    /**
     * As ARIA's {@code findMin(double, double)}: {@code first < second ? first : second}, so a NaN
     * second is returned whenever the comparison fails.
     *
     * @param first a value
     * @param second another
     * @return the smaller
     */
    public static double findMin(double first, double second) {
        return first < second ? first : second;
    }

    /**
     * As ARIA's {@code findMax(double, double)}: {@code first > second ? first : second}.
     *
     * @param first a value
     * @param second another
     * @return the larger
     */
    public static double findMax(double first, double second) {
        return first > second ? first : second;
    }

    // ---- files and paths ----

    /**
     * As ARIA's {@code sizeFile}.
     *
     * @param fileName a file's path
     * @return its size in bytes, or -1 if it cannot be read (missing, a directory, or null)
     */
    public static long sizeFile(String fileName) {
        if (fileName == null) {
            return -1;
        }
        try {
            Path p = Paths.get(fileName);
            return Files.isRegularFile(p) ? Files.size(p) : -1;
        } catch (IOException | RuntimeException e) {
            return -1;
        }
    }

    /**
     * As ARIA's {@code findFile}: whether the file exists and can be opened for reading.
     *
     * @param fileName a file's path
     * @return true if it is a readable file; false otherwise, and for null
     */
    public static boolean findFile(String fileName) {
        if (fileName == null) {
            return false;
        }
        try {
            Path p = Paths.get(fileName);
            return Files.isRegularFile(p) && Files.isReadable(p);
        } catch (RuntimeException e) {
            return false;
        }
    }

    /**
     * As ARIA's {@code getStringFromFile}: the file's first line, without its line end.
     *
     * @param fileName a file's path
     * @return the first line ("" for a file whose first line is empty), or null if the file cannot be
     *         read or is empty (ARIA returns false then)
     */
    public static String getStringFromFile(String fileName) {
        if (fileName == null) {
            return null;
        }
        try (BufferedReader r = Files.newBufferedReader(Paths.get(fileName), StandardCharsets.ISO_8859_1)) {
            return r.readLine();
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    /** @return the platform's directory separator, as ARIA's {@code getSlash} ('/' on Linux, '\\' on Windows) */
    public static char getSlash() {
        return File.separatorChar;
    }

    private static char otherSlash() {
        return File.separatorChar == '/' ? '\\' : '/';
    }

    /**
     * As ARIA's {@code appendSlash(std::string&)}: adds the platform's separator unless the path
     * already ends in either slash; an empty path becomes just the separator.
     *
     * @param path a path
     * @return the path ending in a slash
     */
    public static String appendSlash(String path) {
        if (path.isEmpty() || (path.charAt(path.length() - 1) != '/' && path.charAt(path.length() - 1) != '\\')) {
            return path + getSlash();
        }
        return path;
    }

    /**
     * As ARIA's {@code fixSlashes}: every slash of the other platform's kind turned into this one's.
     *
     * @param path a path
     * @return the path with the platform's separators
     */
    public static String fixSlashes(String path) {
        return path.replace(otherSlash(), getSlash());
    }

    /** @param path a path @return it with every backslash turned into '/', as ARIA's {@code fixSlashesForward} */
    public static String fixSlashesForward(String path) {
        return path.replace('\\', '/');
    }

    /** @param path a path @return it with every '/' turned into a backslash, as ARIA's {@code fixSlashesBackward} */
    public static String fixSlashesBackward(String path) {
        return path.replace('/', '\\');
    }

    /**
     * As ARIA's {@code addDirectories}: {@code baseDir}, a separator, {@code insideDir} and a final
     * separator, all slashes made the platform's ({@code "a"} and {@code "b"} give {@code "a/b/"} on
     * Linux; an empty {@code baseDir} gives {@code "/b/"}, as ARIA's does).
     *
     * @param baseDir   the outer directory
     * @param insideDir the directory inside it
     * @return the joined path
     */
    public static String addDirectories(String baseDir, String insideDir) {
        return fixSlashes(appendSlash(appendSlash(baseDir) + insideDir));
    }

    /**
     * As ARIA's {@code getDirectory}: the path up to its last separator (after {@link #fixSlashes}).
     *
     * @param fileName a path
     * @return the directory part, "" if the name has no directory; null for null or "" (ARIA returns
     *         false there)
     */
    public static String getDirectory(String fileName) {
        if (fileName == null || fileName.isEmpty()) {
            LOG.fine("ArUtil.getDirectory: no file name");
            return null;
        }
        String fixed = fixSlashes(fileName);
        int at = fixed.lastIndexOf(getSlash());
        return at < 0 ? "" : fixed.substring(0, at);
    }

    /**
     * As ARIA's {@code getFileName}: the path after its last separator (after {@link #fixSlashes}).
     *
     * @param fileName a path
     * @return the file's name, the whole argument if it has no directory, "" if it ends in a
     *         separator; null for null or "" (ARIA returns false there)
     */
    public static String getFileName(String fileName) {
        if (fileName == null || fileName.isEmpty()) {
            LOG.fine("ArUtil.getFileName: no file name");
            return null;
        }
        String fixed = fixSlashes(fileName);
        return fixed.substring(fixed.lastIndexOf(getSlash()) + 1);
    }

    /**
     * As ARIA's {@code insertSuffixBeforeExtension}: {@code suffix} goes before the last '.' of the
     * whole name (a '.' in a directory's name counts too, as in ARIA), or at the end if there is none.
     *
     * @param filename a file name
     * @param suffix   the text to insert
     * @return the new name
     */
    public static String insertSuffixBeforeExtension(String filename, String suffix) {
        int dot = filename.lastIndexOf('.');
        return dot < 0 ? filename + suffix : filename.substring(0, dot) + suffix + filename.substring(dot);
    }

    // ---- strings ----

    /**
     * As ARIA's {@code ArUtil::strcmp} (all four forms): C's strcmp with ARIA's rule for null.
     *
     * @param str  a string or null
     * @param str2 a string or null
     * @return -1, 0 or 1 as {@code str} sorts before, with or after {@code str2} by character code;
     *         null sorts before any string and two nulls are equal
     */
    public static int strcmp(String str, String str2) {
        if (str == null || str2 == null) {
            return str == null ? (str2 == null ? 0 : -1) : 1;
        }
        return Integer.signum(str.compareTo(str2));
    }

    /**
     * As ARIA's {@code ArUtil::strcasecmp} (all four forms): C's strcasecmp, which compares the
     * ASCII-lower-cased characters (so {@code "_"} sorts before {@code "A"}, since '_' comes before
     * 'a'), with {@link #strcmp}'s rule for null.
     *
     * @param str  a string or null
     * @param str2 a string or null
     * @return -1, 0 or 1
     */
    public static int strcasecmp(String str, String str2) {
        if (str == null || str2 == null) {
            return strcmp(str, str2);
        }
        return Integer.signum(lower(str).compareTo(lower(str2)));
    }

    /**
     * As ARIA's {@code strSuffixCmp}, rule and all: true only if {@code str} ends with
     * {@code suffix} and is at least two characters longer than it ({@code "a.p"} does not end in
     * {@code ".p"} by this rule; {@code "ab.p"} does), and neither is null or empty.
     *
     * @param str    a string
     * @param suffix the ending sought
     * @return whether {@code str} has the suffix by ARIA's rule
     */
    public static boolean strSuffixCmp(String str, String suffix) {
        return str != null && !str.isEmpty() && suffix != null && !suffix.isEmpty()
                && str.length() > suffix.length() + 1 && str.endsWith(suffix);
    }

    /**
     * As ARIA's {@code strSuffixCaseCmp}: {@link #strSuffixCmp}'s rule, ignoring ASCII case.
     *
     * @param str    a string
     * @param suffix the ending sought
     * @return whether {@code str} has the suffix by ARIA's rule
     */
    public static boolean strSuffixCaseCmp(String str, String suffix) {
        return str != null && suffix != null && strSuffixCmp(lower(str), lower(suffix));
    }

    /**
     * As ARIA's {@code strcasequotecmp}: compares ignoring ASCII case and a pair of double quotes
     * around either string ({@code "\"Robot\""} equals {@code "robot"}); a lone quote is kept.
     *
     * @param str1 a string
     * @param str2 another
     * @return -1, 0 or 1
     */
    public static int strcasequotecmp(String str1, String str2) {
        return Integer.signum(unquoted(lower(str1)).compareTo(unquoted(lower(str2))));
    }

    private static String unquoted(String s) {
        return s.length() >= 2 && s.charAt(0) == '"' && s.charAt(s.length() - 1) == '"'
                ? s.substring(1, s.length() - 1) : s;
    }

    /**
     * As ARIA's {@code escapeSpaces}: a backslash before each space.
     *
     * @param src a string
     * @return the string with its spaces escaped
     */
    public static String escapeSpaces(String src) {
        return src.replace(" ", "\\ ");
    }

    /**
     * As ARIA's {@code stripQuotes}: if the string is at least two characters long and starts and
     * ends with a double quote, those two go; otherwise it is returned as it is. Quotes inside stay.
     *
     * @param str a string
     * @return the string without its surrounding quotes; null for null (ARIA returns false)
     */
    public static String stripQuotes(String str) {
        return str == null ? null : unquoted(str);
    }

    /**
     * As ARIA's {@code fixBadCharacters(str, removeSpaces, fixOtherWhiteSpace)}: the brackets
     * {@code ( { <} become {@code [}, {@code ) } >} become {@code ]}, the characters
     * {@code ! @ # $ % ^ & * = | \ ' " : ; ? / ~ `} become {@code -}; with {@code removeSpaces}
     * every white-space character becomes {@code -}; without it spaces stay and, with
     * {@code fixOtherWhiteSpace}, other white space (tab, newline, ...) becomes a space.
     *
     * @param str                a string
     * @param removeSpaces       whether white space becomes '-'
     * @param fixOtherWhiteSpace whether, keeping spaces, other white space becomes a space
     * @return the fixed string; null for null (ARIA returns false)
     */
    public static String fixBadCharacters(String str, boolean removeSpaces, boolean fixOtherWhiteSpace) {
        if (str == null) {
            return null;
        }
        StringBuilder b = new StringBuilder(str);
        for (int i = 0; i < b.length(); i++) {
            char c = b.charAt(i);
            if (!removeSpaces && c == ' ') {
                continue;
            } else if (!removeSpaces && fixOtherWhiteSpace && isCSpace(c)) {
                b.setCharAt(i, ' ');
            } else if (c == '(' || c == '{' || c == '<') {
                b.setCharAt(i, '[');
            } else if (c == ')' || c == '}' || c == '>') {
                b.setCharAt(i, ']');
            } else if (removeSpaces && isCSpace(c)) {
                b.setCharAt(i, '-');
            } else if ("!@#$%^&*=|\\'\":;?/~`".indexOf(c) >= 0) {
                b.setCharAt(i, '-');
            }
        }
        return b.toString();
    }

    /**
     * As {@link #fixBadCharacters(String, boolean, boolean)} with ARIA's default
     * {@code fixOtherWhiteSpace} of true.
     *
     * @param str          a string
     * @param removeSpaces whether white space becomes '-'
     * @return the fixed string; null for null
     */
    public static String fixBadCharacters(String str, boolean removeSpaces) {
        return fixBadCharacters(str, removeSpaces, true);
    }

    /** @return whether C's isspace holds for the character in the C locale */
    private static boolean isCSpace(char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == 0x0B || c == '\f' || c == '\r';
    }

    private static boolean isCDigit(char c) {
        return c >= '0' && c <= '9';
    }

    /** @return whether the character is an ASCII digit of the radix (10 or 16) */
    private static boolean isDigitIn(char c, int radix) {
        return c < 128 && Character.digit(c, radix) >= 0;
    }

    private static boolean isCAlpha(char c) {
        return c >= 'a' && c <= 'z' || c >= 'A' && c <= 'Z';
    }

    /**
     * As ARIA's {@code lower}: C's tolower on each character, so only A to Z change.
     *
     * @param src a string
     * @return it with ASCII capitals made small
     */
    public static String lower(String src) {
        StringBuilder b = new StringBuilder(src.length());
        for (int i = 0; i < src.length(); i++) {
            char c = src.charAt(i);
            b.append(c >= 'A' && c <= 'Z' ? (char) (c + ('a' - 'A')) : c);
        }
        return b.toString();
    }

    /**
     * As ARIA's {@code isOnlyAlphaNumeric}: only ASCII letters, digits, '+' and '-' (ARIA allows
     * those two); true for an empty string and for null.
     *
     * @param str a string
     * @return whether it holds nothing else
     */
    public static boolean isOnlyAlphaNumeric(String str) {
        if (str == null) {
            return true;
        }
        for (int i = 0; i < str.length(); i++) {
            char c = str.charAt(i);
            if (!isCAlpha(c) && !isCDigit(c) && c != '+' && c != '-') {
                return false;
            }
        }
        return true;
    }

    /**
     * As ARIA's {@code isOnlyNumeric}: only digits, '+' and '-' (no '.' or ','); true for an empty
     * string and for null.
     *
     * @param str a string
     * @return whether it holds nothing else
     */
    public static boolean isOnlyNumeric(String str) {
        if (str == null) {
            return true;
        }
        for (int i = 0; i < str.length(); i++) {
            char c = str.charAt(i);
            if (!isCDigit(c) && c != '+' && c != '-') {
                return false;
            }
        }
        return true;
    }

    /** @param str a string @return whether it is null or empty, as ARIA's {@code isStrEmpty} */
    public static boolean isStrEmpty(String str) {
        return str == null || str.isEmpty();
    }

    /**
     * As ARIA's {@code isStrInList}.
     *
     * @param str          a string
     * @param list         the strings to look in
     * @param isIgnoreCase whether to compare as {@link #strcasecmp} does
     * @return whether one of them equals {@code str}; false for a null {@code str}
     */
    public static boolean isStrInList(String str, Collection<String> list, boolean isIgnoreCase) {
        if (str == null) {
            return false;
        }
        for (String s : list) {
            if (isIgnoreCase ? strcasecmp(s, str) == 0 : strcmp(s, str) == 0) {
                return true;
            }
        }
        return false;
    }

    /**
     * As {@link #isStrInList(String, Collection, boolean)} with ARIA's default, case counted.
     *
     * @param str  a string
     * @param list the strings to look in
     * @return whether one of them equals {@code str}
     */
    public static boolean isStrInList(String str, Collection<String> list) {
        return isStrInList(str, list, false);
    }

    /**
     * As ARIA's {@code convertBool}.
     *
     * @param val an int read as C reads a truth value
     * @return {@link #TRUESTRING} for any value but 0, {@link #FALSESTRING} for 0
     */
    public static String convertBool(int val) {
        return val != 0 ? TRUESTRING : FALSESTRING;
    }

    // ---- numbers from text ----

    /**
     * As ARIA's {@code ArUtil::atof}: C's atof, with "inf" and "-inf" (any case) as infinities. Like
     * C's, it reads the longest number at the start of the string (after white space) and ignores
     * the rest: {@code "12.5mm"} is 12.5, {@code "1e3"} 1000, {@code "nan"} NaN, {@code "0x10"} 16;
     * a string with no number at its start, or null, gives 0.
     *
     * @param nptr a string
     * @return the number
     */
    public static double atof(String nptr) {
        if (nptr == null) {
            return 0;
        }
        double[] out = new double[1];
        return strtod(nptr, out) < 0 ? 0 : out[0];
    }

    /**
     * As ARIA's {@code readDoubleValue}: the whole string must be a number (C's strtod, white space
     * allowed before it but nothing after it).
     *
     * @param buf a string
     * @param ok  null, or an array whose element 0 receives whether the string was a number
     * @return the number, or 0 if it was not one
     */
    public static double readDoubleValue(String buf, boolean[] ok) {
        double[] out = new double[1];
        int end = buf == null ? -1 : strtod(buf, out);
        boolean good = end >= 0 && end == buf.length();
        if (ok != null) {
            ok[0] = good;
        }
        return good ? out[0] : 0;
    }

    /**
     * As ARIA's {@code atoi(str)}: {@link #atoi(String, boolean[], boolean)} without the flag.
     *
     * @param str a string
     * @return the int, or 0 if the string is not one
     */
    public static int atoi(String str) {
        return atoi(str, null, false);
    }

    /**
     * As ARIA's {@code ArUtil::atoi(str, ok, forceHex)}: the whole string must be an integer (C's
     * strtol: white space and a sign allowed before it, nothing after it); a string of more than two
     * characters starting with {@code 0x} or {@code 0X} is read in hexadecimal, and so is every
     * string with {@code forceHex}. A value above the int's range fails, as in ARIA; one below it
     * fails here too (ARIA's cast would wrap it on a 64-bit Linux).
     *
     * @param str      a string
     * @param ok       null, or an array whose element 0 receives whether the string was an int
     * @param forceHex whether to read hexadecimal without a prefix
     * @return the int, or 0 if the string is not one (or is null)
     */
    public static int atoi(String str, boolean[] ok, boolean forceHex) {
        boolean good = false;
        long value = 0;
        if (str != null) {
            int base = forceHex ? 16 : 10;
            String s = str;
            if (s.length() > 2 && s.charAt(0) == '0' && (s.charAt(1) == 'x' || s.charAt(1) == 'X')) {
                s = s.substring(2);
                base = 16;
            }
            long[] out = new long[1];
            int end = strtol(s, base, out);
            if (end == s.length() && out[0] <= Integer.MAX_VALUE && out[0] >= Integer.MIN_VALUE) {
                good = true;
                value = out[0];
            }
        }
        if (ok != null) {
            ok[0] = good;
        }
        return good ? (int) value : 0;
    }

    /**
     * C's strtol: white space, a sign, in base 16 an optional 0x, then digits.
     *
     * @return the index after the last digit, or -1 if there were none (strtol's end pointer at the
     *         start); {@code out[0]} the value, held within a long's range
     */
    private static int strtol(String s, int base, long[] out) {
        int i = 0;
        int n = s.length();
        while (i < n && isCSpace(s.charAt(i))) {
            i++;
        }
        boolean negative = false;
        if (i < n && (s.charAt(i) == '+' || s.charAt(i) == '-')) {
            negative = s.charAt(i) == '-';
            i++;
        }
        if (base == 16 && i + 2 < n && s.charAt(i) == '0' && (s.charAt(i + 1) == 'x' || s.charAt(i + 1) == 'X')
                && isDigitIn(s.charAt(i + 2), 16)) {
            i += 2;
        }
        int start = i;
        long v = 0;
        boolean overflow = false;
        while (i < n && isDigitIn(s.charAt(i), base)) {
            int d = Character.digit(s.charAt(i), base);
            if (v > (Long.MAX_VALUE - d) / base) {
                overflow = true;
            } else {
                v = v * base + d;
            }
            i++;
        }
        if (i == start) {
            return -1;
        }
        out[0] = overflow ? (negative ? Long.MIN_VALUE : Long.MAX_VALUE) : negative ? -v : v;
        return i;
    }

    /**
     * C's strtod: white space, a sign, then a decimal number (digits with an optional point and
     * exponent), a hexadecimal one ({@code 0x}, with an optional point and {@code p} exponent),
     * {@code inf}, {@code infinity} or {@code nan} in any case.
     *
     * @return the index after the number, or -1 if there is none; {@code out[0]} the value
     */
    private static int strtod(String s, double[] out) {
        int n = s.length();
        int i = 0;
        while (i < n && isCSpace(s.charAt(i))) {
            i++;
        }
        double sign = 1;
        if (i < n && (s.charAt(i) == '+' || s.charAt(i) == '-')) {
            sign = s.charAt(i) == '-' ? -1 : 1;
            i++;
        }
        String rest = lower(s.substring(i));
        if (rest.startsWith("infinity")) {
            out[0] = sign * Double.POSITIVE_INFINITY;
            return i + 8;
        }
        if (rest.startsWith("inf")) {
            out[0] = sign * Double.POSITIVE_INFINITY;
            return i + 3;
        }
        if (rest.startsWith("nan")) {
            out[0] = Double.NaN;
            int j = i + 3;
            if (j < n && s.charAt(j) == '(') {
                int close = s.indexOf(')', j);
                if (close > 0 && s.substring(j + 1, close).chars().allMatch(c -> c < 128 && (Character.isLetterOrDigit(c) || c == '_'))) {
                    j = close + 1;
                }
            }
            return j;
        }
        boolean hex = rest.length() > 2 && rest.startsWith("0x")
                && (isDigitIn(rest.charAt(2), 16) || rest.charAt(2) == '.' && rest.length() > 3 && isDigitIn(rest.charAt(3), 16));
        int radix = hex ? 16 : 10;
        int j = hex ? i + 2 : i;
        int mantStart = j;
        int digits = 0;
        while (j < n && isDigitIn(s.charAt(j), radix)) {
            j++;
            digits++;
        }
        if (j < n && s.charAt(j) == '.') {
            int k = j + 1;
            while (k < n && isDigitIn(s.charAt(k), radix)) {
                k++;
                digits++;
            }
            j = k;
        }
        if (digits == 0) {
            return -1;
        }
        String mantissa = s.substring(mantStart, j);
        char expMark = hex ? 'p' : 'e';
        String exponent = "0";
        if (j < n && Character.toLowerCase(s.charAt(j)) == expMark) {
            int k = j + 1;
            if (k < n && (s.charAt(k) == '+' || s.charAt(k) == '-')) {
                k++;
            }
            int expDigits = k;
            while (k < n && isCDigit(s.charAt(k))) {
                k++;
            }
            if (k > expDigits) {
                exponent = s.substring(j + 1, k);
                j = k;
            }
        }
        double v;
        try {
            v = hex ? Double.parseDouble("0x" + (mantissa.startsWith(".") ? "0" : "") + mantissa + "p" + exponent)
                    : Double.parseDouble(mantissa + "e" + exponent);
        } catch (NumberFormatException e) {
            // an exponent too long for parseDouble: the value is 0 or infinite by its sign
            v = exponent.startsWith("-") ? 0 : Double.POSITIVE_INFINITY;
        }
        out[0] = sign * v;
        return j;
    }

    // ---- numbers and units ----

    /**
     * As ARIA's {@code floatIsNormal}, which is {@code std::isnormal}: false for 0, subnormal
     * numbers, infinities and NaN (ARIA's comment speaks only of NaN and infinities; its code is
     * isnormal's).
     *
     * @param f a number
     * @return whether it is a normal double
     */
    public static boolean floatIsNormal(double f) {
        return Double.isFinite(f) && Math.abs(f) >= Double.MIN_NORMAL;
    }

    /** @param sec seconds @return milliseconds, as ARIA's {@code secToMSec} */
    public static double secToMSec(double sec) {
        return sec * 1000.0;
    }

    /** @param msec milliseconds @return seconds, as ARIA's {@code mSecToSec} */
    public static double mSecToSec(double msec) {
        return msec / 1000.0;
    }

    /** @param m metres @return US feet, as ARIA's {@code metersToFeet} (× 3.2808399) */
    public static double metersToFeet(double m) {
        return m * 3.2808399;
    }

    /** @param f US feet @return metres, as ARIA's {@code feetToMeters} (÷ 3.2808399) */
    public static double feetToMeters(double f) {
        return f / 3.2808399;
    }
}
