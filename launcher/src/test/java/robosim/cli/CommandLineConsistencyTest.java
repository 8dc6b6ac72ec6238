package robosim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

/**
 * One name, one meaning: an option name that several subcommands show in their --help takes the
 * same kind of value (its label and type) and means the same (its description up to the first
 * ';') in each. Old spellings kept for scripts are hidden, and listed here one by one.
 */
class CommandLineConsistencyTest {
    /** Every hidden option: "command name" and the visible option it is the old name of. */
    private static final Map<String, String> HIDDEN_OLD_NAMES = Map.of(
            "env --port", "--robot-port",
            "viewer --port", "--viewer-port",
            "comms --port", "--viewer-port",
            // control shares the viewer-port options, and so the old name, with comms and viewer
            "control --port", "--viewer-port",
            "demo --out", "--out-dir",
            "demo --max-steps", "--steps",
            "goldfinder --out", "--out-dir",
            "goldfinder --max-steps", "--steps",
            "bench --out", "--out-dir",
            "bench --window", "--rates-every");

    /**
     * The options whose default differs between commands, and why: each is a size or place that
     * belongs to what the command does. Any other shared option has one default.
     */
    private static final Map<String, String> DEFAULTS_PER_COMMAND = Map.of(
            "--steps", "env runs until the robots leave (0), a GoldFinder search stops at 20000, a measurement takes 600",
            "--robots", "goldfinder's team (3), maze's start places (8), bench's counts (1,10,100)",
            "--out-dir", "each command writes to a folder of its own name under out/");

    private record Use(String command, OptionSpec option) {
        String describe() {
            return command + " " + option.longestName() + " " + option.paramLabel() + " (" + elementType(option) + "): "
                    + String.join(" ", option.description());
        }
    }

    private static Map<String, List<Use>> visibleUses() {
        Map<String, List<Use>> uses = new TreeMap<>();
        for (Map.Entry<String, CommandLine> sub : Main.commandLine().getSubcommands().entrySet()) {
            if (sub.getValue().getCommand() instanceof CommandLine.HelpCommand) {
                continue; // picocli's own: its --help is help about help
            }
            for (OptionSpec o : sub.getValue().getCommandSpec().options()) {
                if (o.hidden()) {
                    continue;
                }
                for (String name : o.names()) {
                    uses.computeIfAbsent(name, n -> new ArrayList<>()).add(new Use(sub.getKey(), o));
                }
            }
        }
        return uses;
    }

    @Test
    void anOptionNameShownByTwoCommandsMeansOneThing() {
        List<String> clashes = new ArrayList<>();
        for (Map.Entry<String, List<Use>> e : visibleUses().entrySet()) {
            Use first = e.getValue().get(0);
            for (Use other : e.getValue()) {
                if (!first.option().paramLabel().equals(other.option().paramLabel())
                        || !elementType(first.option()).equals(elementType(other.option()))
                        || first.option().arity().max() == 0 != (other.option().arity().max() == 0)
                        || !meaning(first.option()).equals(meaning(other.option()))) {
                    clashes.add(e.getKey() + ":\n  " + first.describe() + "\n  " + other.describe());
                }
            }
        }
        assertTrue(clashes.isEmpty(), "one name, two meanings:\n" + String.join("\n", clashes));
    }

    @Test
    void anOptionNameShownByTwoCommandsHasOneDefaultUnlessListed() {
        List<String> differ = new ArrayList<>();
        for (Map.Entry<String, List<Use>> e : visibleUses().entrySet()) {
            Set<String> defaults = new TreeSet<>();
            e.getValue().forEach(u -> defaults.add(String.valueOf(u.option().defaultValue())));
            if (defaults.size() > 1) {
                differ.add(e.getKey());
                assertTrue(DEFAULTS_PER_COMMAND.containsKey(e.getKey()),
                        e.getKey() + " has the defaults " + defaults + " in different commands");
            }
        }
        assertEquals(new TreeSet<>(DEFAULTS_PER_COMMAND.keySet()), new TreeSet<>(differ),
                "the list of defaults that differ is up to date");
    }

    @Test
    void theOnlyHiddenOptionsAreTheListedOldNamesAndEachStillWorks() {
        Map<String, String> hidden = new TreeMap<>();
        for (Map.Entry<String, CommandLine> sub : Main.commandLine().getSubcommands().entrySet()) {
            CommandSpec spec = sub.getValue().getCommandSpec();
            for (OptionSpec o : spec.options()) {
                if (o.hidden()) {
                    String visible = String.join(" ", o.description()).replace(OptionTexts.OLD_NAME, "");
                    hidden.put(sub.getKey() + " " + o.longestName(), visible);
                    OptionSpec now = spec.findOption(visible);
                    assertTrue(now != null && !now.hidden(), sub.getKey() + " " + o.longestName() + " stands for "
                            + visible + ", which it shows");
                    assertEquals(now.paramLabel(), o.paramLabel(), o.longestName() + " takes what " + visible + " takes");
                    assertEquals(elementType(now), elementType(o), o.longestName() + " takes what " + visible + " takes");
                }
            }
        }
        assertEquals(new TreeMap<>(HIDDEN_OLD_NAMES), hidden);
    }

    @Test
    void noHelpShowsAnOldName() {
        for (Map.Entry<String, CommandLine> sub : Main.commandLine().getSubcommands().entrySet()) {
            String help = sub.getValue().getUsageMessage(CommandLine.Help.Ansi.OFF);
            for (String entry : HIDDEN_OLD_NAMES.keySet()) {
                String[] commandAndName = entry.split(" ");
                if (commandAndName[0].equals(sub.getKey())) {
                    assertFalse(help.matches("(?s).*" + commandAndName[1] + "[ =].*"), sub.getKey() + " --help shows "
                            + commandAndName[1] + ":\n" + help);
                }
            }
        }
    }

    /** @return the description up to its first ';': what the name means, before what this command adds */
    private static String meaning(OptionSpec o) {
        String d = String.join(" ", o.description());
        int semicolon = d.indexOf(';');
        return semicolon < 0 ? d : d.substring(0, semicolon);
    }

    /** @return the type of one value: int for an int, and for a list of Integer too */
    private static String elementType(OptionSpec o) {
        Class<?> t = o.typeInfo().isMultiValue() ? o.typeInfo().getAuxiliaryTypes()[0] : o.typeInfo().getType();
        return t == Integer.class ? "int" : t == Long.class ? "long" : t == Double.class ? "double"
                : t == Boolean.class ? "boolean" : t.getName();
    }
}
