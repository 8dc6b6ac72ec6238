package robosim.experiment;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A value of the experiment file that may name factors, {@code ${team}} or {@code "--loss=${loss}"},
 * filled in for each run; with the line it was written on, for errors.
 *
 * @param text as written
 * @param line its line in the file
 */
record Template(String text, int line) {
    /** {@code ${name}}: a factor's name or one of {@link #BUILT_IN}. */
    static final Pattern PLACEHOLDER = Pattern.compile("\\$\\{([^}]*)}");
    /** The names every run fills in besides its factors. */
    static final Set<String> BUILT_IN = Set.of("seed", "replicate", "run");

    /** @return the names it uses, in order */
    List<String> names() {
        List<String> names = new ArrayList<>();
        Matcher m = PLACEHOLDER.matcher(text);
        while (m.find()) {
            names.add(m.group(1));
        }
        return names;
    }

    /**
     * @param values a value for every name it uses
     * @return the text with each {@code ${name}} replaced
     */
    String fill(Map<String, String> values) {
        Matcher m = PLACEHOLDER.matcher(text);
        StringBuilder out = new StringBuilder();
        while (m.find()) {
            m.appendReplacement(out, Matcher.quoteReplacement(values.get(m.group(1))));
        }
        m.appendTail(out);
        return out.toString();
    }
}
