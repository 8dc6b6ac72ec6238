package robosim.aria;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * ARIA's {@code ArArgumentParser}: a program's command line, from which each part of the program
 * (the robot connector, the laser connector, the program itself) takes the arguments it knows,
 * removing them, so that whatever is left was understood by nobody.
 *
 * <p>As in ARIA, argument 0 is the program's name (here its main class's simple name) and the
 * arguments proper start at 1; argument names match without regard to case, and {@code -name}
 * also matches {@code --name}. Where C++ passes a pointer for the value found, Java passes an
 * array of one, which keeps its value when the argument is absent:
 * <pre>{@code
 * int[] port = {8101};
 * if (!parser.checkParameterArgumentInteger("-port", port)) { ...bad value... }
 * }</pre>
 *
 * <p>{@link #loadDefaultArguments()} adds the arguments of the file {@code /etc/Aria.args} and of
 * the environment variable {@code ARIAARGS}, as ARIA does (see {@link #addDefaultArgumentFile} and
 * {@link #addDefaultArgumentEnv}).
 */
public class ArArgumentParser {
    /** Where default arguments come from: files and environment variables, in order. */
    private static final List<String[]> DEFAULT_LOCATIONS = new CopyOnWriteArrayList<>(List.of(
            new String[] {"file", "/etc/Aria.args"}, new String[] {"env", "ARIAARGS"}));

    private final List<String> argv = new ArrayList<>();
    private final String starting;
    private boolean reallySetOnlyTrue;
    private boolean help;

    /**
     * @param args the program's arguments, as {@code main} gets them (without the program's name)
     */
    public ArArgumentParser(String[] args) {
        argv.add(programName());
        argv.addAll(List.of(args));
        starting = String.join(" ", args);
    }

    /** @return the simple name of the class whose {@code main} the thread runs (the nearest), or {@code java} */
    private static String programName() {
        return StackWalker.getInstance(StackWalker.Option.RETAIN_CLASS_REFERENCE).walk(frames -> frames
                .filter(f -> f.getMethodName().equals("main"))
                .findFirst()
                .map(f -> f.getDeclaringClass().getSimpleName())
                .orElse("java"));
    }

    /**
     * @param onlyTrue whether a {@code wasReallySet} is only ever set to true (ARIA's: a later check
     *                 of another name for the same value does not clear it)
     */
    public void setWasReallySetOnlyTrue(boolean onlyTrue) {
        reallySetOnlyTrue = onlyTrue;
    }

    /** @return whether a {@code wasReallySet} is only ever set to true */
    public boolean getWasReallySetOnlyTrue() {
        return reallySetOnlyTrue;
    }

    private boolean matches(String argument, String given) {
        return given.equalsIgnoreCase(argument) || given.equalsIgnoreCase("-" + argument);
    }

    /**
     * Takes a flag.
     *
     * @param argument the flag, e.g. {@code -remoteIsSim}
     * @return whether it was given (it is removed)
     */
    public boolean checkArgument(String argument) {
        for (int i = 0; i < argv.size(); i++) {
            if (matches(argument, argv.get(i))) {
                argv.remove(i);
                return true;
            }
        }
        return false;
    }

    /**
     * Takes an argument and its value; when it is given more than once, the last is taken (and all
     * are removed), as in ARIA.
     *
     * @param argument the argument, e.g. {@code -remoteHost}
     * @return its value; "" when it is last with no value after it; null when it is not given
     */
    public String checkParameterArgument(String argument) {
        return checkParameterArgument(argument, false);
    }

    /**
     * @param argument    the argument
     * @param returnFirst take the first one given, leaving any later ones
     * @return its value, "" when it has none, null when it is not given
     */
    public String checkParameterArgument(String argument, boolean returnFirst) {
        String found = null;
        for (int i = 0; i < argv.size(); i++) {
            if (matches(argument, argv.get(i))) {
                argv.remove(i);
                found = i < argv.size() ? argv.remove(i) : "";
                if (returnFirst) {
                    return found;
                }
                i--;
            }
        }
        return found;
    }

    /**
     * @param argument the argument
     * @param dest     its value goes in {@code dest[0]} when given
     * @return false if it was given without a value (logged); true otherwise
     */
    public boolean checkParameterArgumentString(String argument, String[] dest) {
        return checkParameterArgumentString(argument, dest, null, false);
    }

    /**
     * @param argument     the argument
     * @param dest         its value goes in {@code dest[0]} when given
     * @param wasReallySet {@code wasReallySet[0]} says whether it was given, or null
     * @param returnFirst  take the first one given
     * @return false if it was given without a value (logged); true otherwise
     */
    public boolean checkParameterArgumentString(String argument, String[] dest, boolean[] wasReallySet,
                                                boolean returnFirst) {
        String value = taken(argument, wasReallySet, returnFirst);
        if (value == null) {
            return true;
        }
        if (value.isEmpty()) {
            return false;
        }
        dest[0] = value;
        return true;
    }

    /**
     * @param argument the argument
     * @param dest     its value goes in {@code dest[0]} when given: a whole number
     * @return false if it was given without a value or with one that is not an int (logged)
     */
    public boolean checkParameterArgumentInteger(String argument, int[] dest) {
        return checkParameterArgumentInteger(argument, dest, null, false);
    }

    /**
     * @param argument     the argument
     * @param dest         its value goes in {@code dest[0]} when given
     * @param wasReallySet {@code wasReallySet[0]} says whether it was given, or null
     * @param returnFirst  take the first one given
     * @return false if it was given without a value or with one that is not an int (logged)
     */
    public boolean checkParameterArgumentInteger(String argument, int[] dest, boolean[] wasReallySet,
                                                 boolean returnFirst) {
        return number(argument, wasReallySet, returnFirst, "an integer", v -> dest[0] = Integer.parseInt(v));
    }

    /**
     * @param argument the argument
     * @param dest     its value goes in {@code dest[0]} when given: a number
     * @return false if it was given without a value or with one that is not a number (logged)
     */
    public boolean checkParameterArgumentDouble(String argument, double[] dest) {
        return checkParameterArgumentDouble(argument, dest, null, false);
    }

    /**
     * @param argument     the argument
     * @param dest         its value goes in {@code dest[0]} when given
     * @param wasReallySet {@code wasReallySet[0]} says whether it was given, or null
     * @param returnFirst  take the first one given
     * @return false if it was given without a value or with one that is not a number (logged)
     */
    public boolean checkParameterArgumentDouble(String argument, double[] dest, boolean[] wasReallySet,
                                                boolean returnFirst) {
        return number(argument, wasReallySet, returnFirst, "a double", v -> dest[0] = Double.parseDouble(v));
    }

    /** Takes a number argument: {@code set} parses and keeps it, throwing if it is not one (logged as ARIA's). */
    private boolean number(String argument, boolean[] wasReallySet, boolean returnFirst, String kind,
                           java.util.function.Consumer<String> set) {
        String value = taken(argument, wasReallySet, returnFirst);
        if (value == null) {
            return true;
        }
        if (value.isEmpty()) {
            return false;
        }
        try {
            set.accept(value);
            return true;
        } catch (NumberFormatException e) {
            ArLog.log(ArLog.Normal, "Argument given to %s was not %s it was the string %s", argument, kind, value);
            reallySet(wasReallySet, false);
            return false;
        }
    }

    /**
     * @param argument the argument
     * @param dest     its value goes in {@code dest[0]} when given: true, false, 1 or 0
     * @return false if it was given without a value or with another (logged)
     */
    public boolean checkParameterArgumentBool(String argument, boolean[] dest) {
        return checkParameterArgumentBool(argument, dest, null, false);
    }

    /**
     * @param argument     the argument
     * @param dest         its value goes in {@code dest[0]} when given: true, false, 1 or 0
     * @param wasReallySet {@code wasReallySet[0]} says whether it was given, or null
     * @param returnFirst  take the first one given
     * @return false if it was given without a value or with another (logged)
     */
    public boolean checkParameterArgumentBool(String argument, boolean[] dest, boolean[] wasReallySet,
                                              boolean returnFirst) {
        String value = taken(argument, wasReallySet, returnFirst);
        if (value == null) {
            return true;
        }
        if (value.equalsIgnoreCase("true") || value.equals("1")) {
            dest[0] = true;
            return true;
        }
        if (value.equalsIgnoreCase("false") || value.equals("0")) {
            dest[0] = false;
            return true;
        }
        if (!value.isEmpty()) {
            ArLog.log(ArLog.Normal, "Argument given to %s was not a bool (true, false, 1, 0) it was the string %s",
                    argument, value);
            reallySet(wasReallySet, false);
        }
        return false;
    }

    /** The value given, with {@code wasReallySet} kept; "" logged as a missing value. */
    private String taken(String argument, boolean[] wasReallySet, boolean returnFirst) {
        String value = checkParameterArgument(argument, returnFirst);
        if (value == null) {
            if (!reallySetOnlyTrue) {
                reallySet(wasReallySet, false);
            }
            return null;
        }
        if (value.isEmpty()) {
            ArLog.log(ArLog.Normal, "No argument given to %s", argument);
            return "";
        }
        reallySet(wasReallySet, true);
        return value;
    }

    private static void reallySet(boolean[] wasReallySet, boolean set) {
        if (wasReallySet != null) {
            wasReallySet[0] = set;
        }
    }

    /**
     * Adds an argument as if it had been given, at a position (−1: at the end).
     *
     * @param argument the arguments, split at white space (double quotes keep a value whole)
     * @param position where: 1 is first after the program's name
     */
    public void addDefaultArgument(String argument, int position) {
        List<String> words = words(argument);
        int at = position < 0 || position > argv.size() ? argv.size() : Math.max(1, position);
        argv.addAll(at, words);
    }

    /** @param argument the arguments, added at the end as {@link #addDefaultArgument(String, int)} adds them */
    public void addDefaultArgument(String argument) {
        addDefaultArgument(argument, -1);
    }

    /** Adds the default arguments (the files' and environment variables') first after the program's name. */
    public void loadDefaultArguments() {
        loadDefaultArguments(1);
    }

    /**
     * Adds the arguments of each default file and environment variable, in order, at a position.
     *
     * @param position where: 1 is first after the program's name
     */
    public void loadDefaultArguments(int position) {
        List<String> added = new ArrayList<>();
        for (String[] location : DEFAULT_LOCATIONS) {
            String text = null;
            if (location[0].equals("env")) {
                text = System.getenv(location[1]);
                if (text != null) {
                    ArLog.log(ArLog.Normal, "Added arguments from environmental variable '%s'", location[1]);
                }
            } else {
                Path file = Path.of(location[1]);
                if (Files.isReadable(file)) {
                    try {
                        text = Files.readString(file, StandardCharsets.UTF_8);
                        ArLog.log(ArLog.Normal, "Added arguments from file '%s'", location[1]);
                    } catch (IOException e) {
                        ArLog.log(ArLog.Normal, "Could not read arguments from file '%s': %s", location[1], e.getMessage());
                    }
                }
            }
            if (text != null) {
                added.addAll(words(text));
            }
        }
        int at = Math.min(Math.max(1, position), argv.size());
        argv.addAll(at, added);
    }

    /** @param file a file whose arguments {@link #loadDefaultArguments()} adds, after those before it */
    public static void addDefaultArgumentFile(String file) {
        DEFAULT_LOCATIONS.add(new String[] {"file", file});
    }

    /** @param env an environment variable whose arguments {@link #loadDefaultArguments()} adds */
    public static void addDefaultArgumentEnv(String env) {
        DEFAULT_LOCATIONS.add(new String[] {"env", env});
    }

    /** Logs where default arguments come from. */
    public static void logDefaultArgumentLocations() {
        ArLog.log(ArLog.Normal, "Default arguments loaded from:");
        for (String[] location : DEFAULT_LOCATIONS) {
            ArLog.log(ArLog.Normal, "%s %s", location[0].equals("env") ? "Environment variable" : "File", location[1]);
        }
    }

    /** Splits at white space; double quotes keep what they enclose as one word. */
    static List<String> words(String text) {
        List<String> out = new ArrayList<>();
        StringBuilder word = new StringBuilder();
        boolean quoted = false;
        boolean any = false;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '"') {
                quoted = !quoted;
                any = true;
            } else if (Character.isWhitespace(c) && !quoted) {
                if (any) {
                    out.add(word.toString());
                    word.setLength(0);
                    any = false;
                }
            } else {
                word.append(c);
                any = true;
            }
        }
        if (any) {
            out.add(word.toString());
        }
        return out;
    }

    /**
     * Takes {@code -help}, {@code -h}, {@code /?} or {@code /h}.
     *
     * @return false if help was asked for (then the program logs its options and exits)
     */
    public boolean checkHelp() {
        if (help || checkArgument("-help") || checkArgument("-h") || checkArgument("/?") || checkArgument("/h")) {
            help = true;
            return false;
        }
        return true;
    }

    /**
     * Checks for help, and logs the arguments nobody took (the program goes on).
     *
     * @return false if help was asked for
     */
    public boolean checkHelpAndWarnUnparsed() {
        return checkHelpAndWarnUnparsed(0);
    }

    /**
     * @param numArgsOkay arguments after the program's name that may be left
     * @return false if help was asked for
     */
    public boolean checkHelpAndWarnUnparsed(int numArgsOkay) {
        if (!checkHelp()) {
            return false;
        }
        if (argv.size() <= 1 + numArgsOkay) {
            return true;
        }
        ArLog.log(ArLog.Normal, "Unhandled arguments to program: %s",
                String.join(" ", argv.subList(1 + numArgsOkay, argv.size())));
        ArLog.log(ArLog.Normal, "Program will continue but to see the help listing type '%s -help'", argv.get(0));
        return true;
    }

    /** @return the arguments left, the program's name included */
    public int getArgc() {
        return argv.size();
    }

    /** @return a copy of the arguments left, the program's name first */
    public String[] getArgv() {
        return argv.toArray(String[]::new);
    }

    /**
     * @param which 0 for the program's name, 1 for the first argument left, ...
     * @return it, or null past the end
     */
    public String getArg(int which) {
        return which >= 0 && which < argv.size() ? argv.get(which) : null;
    }

    /** @param which the argument to remove (1 and on; the program's name stays) */
    public void removeArg(int which) {
        if (which > 0 && which < argv.size()) {
            argv.remove(which);
        }
    }

    /** @return the arguments as the program was given them */
    public String getStartingArguments() {
        return starting;
    }

    /** Logs the arguments left. */
    public void log() {
        ArLog.log(ArLog.Terse, "Num arguments: %d", argv.size());
        for (int i = 0; i < argv.size(); i++) {
            ArLog.log(ArLog.Terse, "Arg %d: %s", i, argv.get(i));
        }
    }
}
