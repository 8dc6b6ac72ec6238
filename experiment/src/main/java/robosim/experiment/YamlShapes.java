package robosim.experiment;

import java.nio.file.Path;
import java.util.List;
import robosim.experiment.YamlTree.Mapping;
import robosim.experiment.YamlTree.Node;
import robosim.experiment.YamlTree.Scalar;

/**
 * The shapes an experiment file's nodes must have (a mapping of known keys, a single value, a whole
 * number in a range), each broken one told with the file, the line and the rule.
 */
final class YamlShapes {
    private final Path file;

    YamlShapes(Path file) {
        this.file = file;
    }

    Mapping mapping(Node node, String what) {
        if (node instanceof Mapping m) {
            return m;
        }
        throw new ExperimentFileException(file, node.line(), what + " is " + node.kind() + ": it must be a mapping"
                + " of keys to values");
    }

    void keys(Mapping m, List<String> known, String what) {
        for (String k : m.entries().keySet()) {
            if (!known.contains(k)) {
                throw new ExperimentFileException(file, m.keyLines().get(k), "'" + k + "' is no key of " + what
                        + ": its keys are " + String.join(", ", known));
            }
        }
    }

    void require(Mapping m, String key, String what) {
        if (!m.entries().containsKey(key)) {
            throw new ExperimentFileException(file, m.line(), what + " has no " + key + ": it is required");
        }
    }

    String scalar(Node node, String what) {
        if (node instanceof Scalar s && !s.isNull()) {
            return s.text();
        }
        throw new ExperimentFileException(file, node.line(), what + " is " + node.kind() + ": it must be a single value");
    }

    long whole(Mapping m, String key, long absent, long min, long max) {
        if (!m.entries().containsKey(key)) {
            return absent;
        }
        Node n = m.entries().get(key);
        String v = scalar(n, key);
        try {
            long x = Long.parseLong(v);
            if (x < min || x > max) {
                throw new ExperimentFileException(file, n.line(), x + " is given for " + key + ": it must be from " + min
                        + (max >= Long.MAX_VALUE / 2 ? " up" : " to " + max));
            }
            return x;
        } catch (NumberFormatException e) {
            throw new ExperimentFileException(file, n.line(), "'" + v + "' is given for " + key
                    + ": it must be a whole number");
        }
    }
}
