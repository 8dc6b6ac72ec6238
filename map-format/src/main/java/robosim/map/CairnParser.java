package robosim.map;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Reads the values of a {@code Cairn:} header line:
 * {@code Type x y th "description" ICON "label" [x1 y1 x2 y2] ["description"]}, the four numbers
 * being the from and to points of lines and areas (ARIA's {@code ArMapObject::createMapObject} reads
 * them at the same places: eleven values or more have them).
 */
final class CairnParser {
    /** Type, x, y, th, description, icon, label. */
    private static final int BASE_FIELDS = 7;
    private static final int FROM_TO_FIELDS = 4;

    private CairnParser() {
    }

    static Cairn parse(Path file, int line, String values) {
        List<String> t = tokens(file, line, values);
        if (t.size() < BASE_FIELDS) {
            throw new MapFileException(file, line, "a Cairn has " + t.size() + " values but needs at least "
                    + BASE_FIELDS + ": Type x y th \"description\" ICON \"label\"");
        }
        String type = t.get(0);
        String named = "Cairn " + MapLines.excerpt(type);
        double x = Numbers.coordinate(file, line, t.get(1), named + " x");
        double y = Numbers.coordinate(file, line, t.get(2), named + " y");
        double th = Numbers.parse(file, line, t.get(3), named + " th");
        double[] fromTo = new double[0];
        if (t.size() >= BASE_FIELDS + FROM_TO_FIELDS) {
            fromTo = new double[FROM_TO_FIELDS];
            for (int i = 0; i < FROM_TO_FIELDS; i++) {
                fromTo[i] = Numbers.coordinate(file, line, t.get(BASE_FIELDS + i), named + " corner");
            }
        } else if (type.startsWith("Forbidden")) {
            throw new MapFileException(file, line, "a " + named + " has " + t.size() + " values but needs "
                    + (BASE_FIELDS + FROM_TO_FIELDS) + ": its from and to points follow the label");
        }
        // as ArMapObject::setObjectDescription: a quoted string after the name (and the points) wins
        int descriptionAt = BASE_FIELDS + fromTo.length;
        String description = t.size() > descriptionAt ? t.get(descriptionAt) : t.get(4);
        return new Cairn(type, x, y, th, description, t.get(5), t.get(6), fromTo, line);
    }

    /** Splits on white space, keeping a double-quoted string (quotes removed) as one token. */
    private static List<String> tokens(Path file, int line, String values) {
        List<String> tokens = new ArrayList<>();
        int i = 0;
        int n = values.length();
        while (i < n) {
            char c = values.charAt(i);
            if (Character.isWhitespace(c)) {
                i++;
            } else if (c == '"') {
                int end = values.indexOf('"', i + 1);
                if (end < 0) {
                    throw new MapFileException(file, line, "a Cairn has a quoted string that is not closed");
                }
                tokens.add(values.substring(i + 1, end));
                i = end + 1;
            } else {
                int end = i;
                while (end < n && !Character.isWhitespace(values.charAt(end))) {
                    end++;
                }
                tokens.add(values.substring(i, end));
                i = end;
            }
        }
        return tokens;
    }
}
