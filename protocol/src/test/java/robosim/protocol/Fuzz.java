package robosim.protocol;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.List;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Seeded-random test cases, and the byte and text mutations the fuzz tests apply to valid input
 * (docs/TESTING.md lists the tests). Case {@code i} of seed {@code s} draws from its own
 * {@link Random}, so one case can be replayed alone. Three system properties change a run:
 * {@value #SEED} (the seed), {@value #CASES} (how many cases) and {@value #CASE} (run only that
 * case). A failing case names its seed, its number and its input.
 */
public final class Fuzz {
    /** The system property that replaces every fuzz test's seed. */
    public static final String SEED = "robosim.fuzz.seed";
    /** The system property that sets how many cases each fuzz test runs. */
    public static final String CASES = "robosim.fuzz.cases";
    /** The system property that runs one case alone. */
    public static final String CASE = "robosim.fuzz.case";

    private final Random random;
    private String input = "(not described)";

    private Fuzz(Random random) {
        this.random = random;
    }

    /** One case's body. */
    public interface Body {
        /**
         * @param fuzz the case: its random source, and where it describes its input
         * @throws Exception anything, reported with the seed and the case
         */
        void run(Fuzz fuzz) throws Exception;
    }

    /**
     * Runs the cases.
     *
     * @param seed  the test's own seed, unless {@value #SEED} is set
     * @param cases the test's own number of cases, unless {@value #CASES} is set
     * @param body  one case
     */
    public static void cases(long seed, int cases, Body body) {
        long s = Long.getLong(SEED, seed);
        Integer only = Integer.getInteger(CASE);
        int first = only == null ? 0 : only;
        int end = only == null ? Integer.getInteger(CASES, cases) : only + 1;
        for (int i = first; i < end; i++) {
            Fuzz fuzz = new Fuzz(new Random(s * 0x9E3779B97F4A7C15L + i));
            try {
                body.run(fuzz);
            } catch (Throwable t) {
                throw new AssertionError("fuzz case " + i + " of seed " + s + " failed (replay it alone with -D"
                        + SEED + "=" + s + " -D" + CASE + "=" + i + "): " + t + "\ninput: " + fuzz.input, t);
            }
        }
    }

    /** @return the case's random source */
    public Random random() {
        return random;
    }

    /** @param description the case's input, named in a failure */
    public void input(String description) {
        input = description.length() > 2000 ? description.substring(0, 2000) + "..." : description;
    }

    /** @param bytes the case's input, named in a failure in hex */
    public void input(byte[] bytes) {
        input(bytes.length + " bytes: " + HexFormat.of().formatHex(bytes, 0, Math.min(bytes.length, 1000)));
    }

    /** Lengths, counts and values at the edges of what an int holds. */
    public static final int[] EDGE_INTS = {0, 1, -1, 0x7f, 0x80, 0xff, 0x7fff, 0xffff, Integer.MAX_VALUE, Integer.MIN_VALUE,
        1 << 20, 1 << 24, 1 << 30};

    /**
     * @param valid a valid input
     * @return it, changed by one to four mutations: bit flips, edge values, cuts, random bytes
     *         inserted, parts deleted or repeated; or now and then random bytes only
     */
    public byte[] mutate(byte[] valid) {
        if (random.nextInt(20) == 0) {
            return garbage(random.nextInt(64));
        }
        byte[] b = valid.clone();
        for (int n = 1 + random.nextInt(4); n > 0; n--) {
            b = mutateOnce(b);
        }
        return b;
    }

    private byte[] mutateOnce(byte[] b) {
        int at = b.length == 0 ? 0 : random.nextInt(b.length);
        switch (random.nextInt(8)) {
            case 0 -> {
                if (b.length > 0) {
                    b[at] ^= (byte) (1 << random.nextInt(8));
                }
            }
            case 1 -> {
                if (b.length > 0) {
                    b[at] = (byte) EDGE_INTS[random.nextInt(EDGE_INTS.length)];
                }
            }
            case 2 -> b = Arrays.copyOf(b, at);
            case 3 -> b = splice(b, at, at, garbage(1 + random.nextInt(16)));
            case 4 -> b = splice(b, at, Math.min(b.length, at + 1 + random.nextInt(16)), new byte[0]);
            case 5 -> b = splice(b, at, at, Arrays.copyOfRange(b, at, Math.min(b.length, at + 1 + random.nextInt(32))));
            case 6 -> {
                if (b.length >= 4) {
                    int v = EDGE_INTS[random.nextInt(EDGE_INTS.length)];
                    int p = random.nextInt(b.length - 3);
                    b[p] = (byte) (v >>> 24);
                    b[p + 1] = (byte) (v >>> 16);
                    b[p + 2] = (byte) (v >>> 8);
                    b[p + 3] = (byte) v;
                }
            }
            default -> {
                for (int i = 0; i < 1 + random.nextInt(8) && b.length > 0; i++) {
                    b[random.nextInt(b.length)] = (byte) random.nextInt();
                }
            }
        }
        return b;
    }

    /**
     * @param b    bytes
     * @param from the first byte replaced
     * @param to   the byte after the last one replaced
     * @param with what replaces them
     * @return {@code b} with bytes {@code from} to {@code to} replaced by {@code with}
     */
    public static byte[] splice(byte[] b, int from, int to, byte[] with) {
        byte[] out = new byte[b.length - (to - from) + with.length];
        System.arraycopy(b, 0, out, 0, from);
        System.arraycopy(with, 0, out, from, with.length);
        System.arraycopy(b, to, out, from + with.length, b.length - to);
        return out;
    }

    private static final Pattern NUMBER = Pattern.compile("-?\\d+(\\.\\d+)?");
    private static final Pattern WORD = Pattern.compile("[A-Za-z][A-Za-z0-9]*");
    /** Numbers and words no valid file holds where a number belongs. */
    private static final String[] EDGE_NUMBERS = {"1e308", "-1e308", "1e999", "-1e999", "NaN", "-NaN", "Infinity",
        "-Infinity", "-0", "0", "-1", "4.9e-324", "2.5e-400", "99999999999999999999", "9223372036854775808",
        "2147483648", "-2147483649", "0x10", "1_000", "1,5", "1.5.5", "+", "-", ".", "e5", "1e", "\uff11\uff12",
        "1".repeat(400), "0.0000000000000000000000000000001"};
    /** Lines a text file may hold, broken or hostile: markup, entities, control characters, long lines. */
    private static final String[] EDGE_LINES = {"", " ", "\t", "\r", ";", "<", ">", "&", "&amp;", "&e;", "&#0;",
        "&#xd800;", "<!-- x -->", "<![CDATA[1]]>", "<?xml version=\"1.0\"?>",
        "<!DOCTYPE x [<!ENTITY e SYSTEM \"file:///etc/passwd\">]>",
        "<!DOCTYPE x [<!ENTITY a \"aaaaaaaaaa\"><!ENTITY b \"&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;\">]>",
        "\u0000", "\u0007", "\ufeff", "\ufffe", "\ud83d\ude00", "x".repeat(20_000), "<a>", "</a>", "<a/>",
        "<a b=\"1\" b=\"2\"/>", "=\"\"", "\"", "'"};

    /**
     * @param valid a valid text file, such as a world or a robot parameter file
     * @return it, changed by one to three mutations: numbers replaced by edge values, words swapped
     *         or lengthened, lines repeated, dropped, swapped or replaced by hostile ones (markup,
     *         entities, control characters, nesting thousands of elements deep), characters
     *         inserted or the text cut short
     */
    public String mutateText(String valid) {
        String t = valid;
        for (int n = 1 + random.nextInt(3); n > 0; n--) {
            t = mutateTextOnce(t);
        }
        return t;
    }

    private String mutateTextOnce(String t) {
        List<String> lines = new ArrayList<>(List.of(t.split("\n", -1)));
        int line = random.nextInt(lines.size());
        switch (random.nextInt(10)) {
            case 0, 1, 2 -> {
                return replaceMatch(t, NUMBER, EDGE_NUMBERS[random.nextInt(EDGE_NUMBERS.length)]);
            }
            case 3 -> {
                List<String> words = matches(t, WORD);
                String with = words.isEmpty() ? "x" : random.nextInt(4) == 0 ? words.get(random.nextInt(words.size())).repeat(500)
                        : words.get(random.nextInt(words.size()));
                return replaceMatch(t, WORD, with);
            }
            case 4 -> lines.add(line, lines.get(random.nextInt(lines.size())));
            case 5 -> lines.remove(line);
            case 6 -> lines.add(line, EDGE_LINES[random.nextInt(EDGE_LINES.length)]);
            case 7 -> {
                int depth = random.nextInt(4) == 0 ? 5000 : random.nextInt(50);
                lines.add(line, "<a>".repeat(depth) + "</a>".repeat(random.nextInt(depth + 1)));
            }
            case 8 -> {
                int at = random.nextInt(t.length() + 1);
                String chars = "<>&\"'=;/ \t\n\r0123456789.-e\u0000\u00e9\u2028\ud800";
                StringBuilder b = new StringBuilder(t.substring(0, at));
                for (int i = 1 + random.nextInt(6); i > 0; i--) {
                    b.append(chars.charAt(random.nextInt(chars.length())));
                }
                return b.append(t.substring(at)).toString();
            }
            default -> {
                return t.substring(0, random.nextInt(t.length() + 1));
            }
        }
        return String.join("\n", lines);
    }

    private String replaceMatch(String t, Pattern pattern, String with) {
        List<int[]> spans = new ArrayList<>();
        Matcher m = pattern.matcher(t);
        while (m.find()) {
            spans.add(new int[] {m.start(), m.end()});
        }
        if (spans.isEmpty()) {
            return t + with;
        }
        int[] span = spans.get(random.nextInt(spans.size()));
        return t.substring(0, span[0]) + with + t.substring(span[1]);
    }

    private static List<String> matches(String t, Pattern pattern) {
        List<String> found = new ArrayList<>();
        Matcher m = pattern.matcher(t);
        while (m.find()) {
            found.add(m.group());
        }
        return found;
    }

    /**
     * @param text a text file's bytes
     * @return its lines as readers count them: each ended by a line feed, a carriage return or both
     */
    public static int lines(byte[] text) {
        int lines = 1;
        for (int i = 0; i < text.length; i++) {
            lines += text[i] == '\n' || text[i] == '\r' && (i + 1 == text.length || text[i + 1] != '\n') ? 1 : 0;
        }
        return lines;
    }

    /** @return {@code length} random bytes */
    public byte[] garbage(int length) {
        byte[] g = new byte[length];
        random.nextBytes(g);
        return g;
    }
}
