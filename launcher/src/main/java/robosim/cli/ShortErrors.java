package robosim.cli;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import picocli.CommandLine;
import picocli.CommandLine.IParameterExceptionHandler;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.UnmatchedArgumentException;

/**
 * Says what is wrong with a command line in one line, then where help is, instead of the whole
 * usage: {@code robosim env: Invalid value for option '--port': 'abc' is not an int}, then
 * {@code Try 'robosim env --help'.}; a mistyped subcommand or option gets "did you mean". Exit
 * code 2. Commands throw {@link ParameterException} for a bad value they find themselves, to be
 * told the same way.
 */
final class ShortErrors implements IParameterExceptionHandler {
    /** The exit code for a bad command line. */
    static final int BAD_COMMAND_LINE = 2;

    @Override
    public int handleParseException(ParameterException e, String[] args) {
        CommandLine cl = e.getCommandLine();
        PrintWriter err = cl.getErr();
        String command = cl.getCommandSpec().qualifiedName();
        err.println(command + ": " + line(e));
        err.println("Try '" + command + " --help'.");
        err.flush();
        return BAD_COMMAND_LINE;
    }

    /** @return the one-line message: picocli's reason, with the names meant for a mistyped one */
    static String line(ParameterException e) {
        String message = String.valueOf(e.getMessage()).strip().replaceAll("\\s*\\R\\s*", " ");
        if (!(e instanceof UnmatchedArgumentException u) || u.getUnmatched().isEmpty()) {
            return message;
        }
        CommandLine cl = u.getCommandLine();
        String typed = u.getUnmatched().get(0);
        boolean option = typed.startsWith("-");
        if (!option && cl.getSubcommands().isEmpty()) {
            return message;
        }
        String head = option ? "unknown option '" + typed + "'" : "'" + typed + "' is not a command";
        List<String> meant = similar(typed, option ? visibleOptionNames(cl) : commands(cl), u.getSuggestions());
        if (!meant.isEmpty()) {
            return head + "; did you mean " + String.join(" or ", meant) + "?";
        }
        return option ? head : head + " (the commands are " + String.join(", ", commands(cl)) + ")";
    }

    /**
     * @return up to three names close to what was typed: one or two letters off (a transposed pair
     *         counts as one), then picocli's own suggestions
     */
    static List<String> similar(String typed, List<String> names, List<String> picocli) {
        int most = Math.max(1, Math.min(2, typed.replaceFirst("^-+", "").length() / 3));
        List<String> close = new ArrayList<>(names.stream().filter(n -> distance(typed, n) <= most)
                .sorted(Comparator.comparingInt(n -> distance(typed, n))).toList());
        // picocli's own suggestions only when nothing is that close: they share letters, not spelling
        return (close.isEmpty() ? picocli.stream().filter(names::contains).toList() : close).stream().limit(3).toList();
    }

    /** @return the optimal string alignment distance: insertions, deletions, changes and swaps of neighbours */
    static int distance(String a, String b) {
        int[][] d = new int[a.length() + 1][b.length() + 1];
        for (int i = 0; i <= a.length(); i++) {
            d[i][0] = i;
        }
        for (int j = 0; j <= b.length(); j++) {
            d[0][j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            for (int j = 1; j <= b.length(); j++) {
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                d[i][j] = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + cost);
                if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
                    d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
                }
            }
        }
        return d[a.length()][b.length()];
    }

    private static List<String> commands(CommandLine cl) {
        return cl.getSubcommands().keySet().stream().filter(n -> !n.equals("help")).toList();
    }

    private static List<String> visibleOptionNames(CommandLine cl) {
        List<String> names = new ArrayList<>();
        for (OptionSpec o : cl.getCommandSpec().options()) {
            if (!o.hidden()) {
                names.addAll(List.of(o.names()));
            }
        }
        return names;
    }
}
