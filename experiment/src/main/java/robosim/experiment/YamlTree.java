package robosim.experiment;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.dataformat.yaml.YAMLFactory;
import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A YAML document read as a tree whose every node knows its line, so that a rule broken deep in an
 * experiment file is told with the line it is on. Read with Jackson's YAML parser; a key given twice
 * in one mapping is an error (YAML forbids it, and the parser alone would keep the last).
 */
final class YamlTree {
    /** The most nodes a file may hold: an experiment file is written by hand. */
    static final int MAX_NODES = 100_000;

    private YamlTree() {
    }

    /** A node of the tree, with the line it begins on. */
    sealed interface Node permits Mapping, Sequence, Scalar {
        /** @return its line, from 1 */
        int line();

        /** @return what it is, for messages: "a mapping", "a list", "a value" */
        String kind();
    }

    /** A mapping, its keys in the file's order. */
    record Mapping(Map<String, Node> entries, Map<String, Integer> keyLines, int line) implements Node {
        @Override
        public String kind() {
            return "a mapping";
        }
    }

    /** A list. */
    record Sequence(List<Node> items, int line) implements Node {
        @Override
        public String kind() {
            return "a list";
        }
    }

    /**
     * A scalar: its text as written, and whether YAML read it as a string (quoted or plain words) or
     * as a number, boolean or null.
     */
    record Scalar(String text, JsonToken token, int line) implements Node {
        @Override
        public String kind() {
            return token == JsonToken.VALUE_NULL ? "empty" : "a value";
        }

        boolean isNull() {
            return token == JsonToken.VALUE_NULL;
        }
    }

    /**
     * @param file the file
     * @return its document's root
     * @throws ExperimentFileException if it is not well-formed YAML, is empty, or gives a key twice
     * @throws IOException             if it cannot be read
     */
    static Node read(Path file) throws IOException {
        try (Reader in = Files.newBufferedReader(file, StandardCharsets.UTF_8);
             JsonParser p = new YAMLFactory().createParser(in)) {
            JsonToken first = p.nextToken();
            if (first == null) {
                throw new ExperimentFileException(file, 0, "the file is empty: an experiment file is a YAML mapping");
            }
            int[] count = {0};
            Node root = node(file, p, count);
            if (p.nextToken() != null) {
                throw new ExperimentFileException(file, line(p), "a second YAML document: an experiment file is one"
                        + " document (leave out the '---')");
            }
            return root;
        } catch (JsonProcessingException e) {
            int line = e.getLocation() == null ? 0 : e.getLocation().getLineNr();
            throw new ExperimentFileException(file, line, "not well-formed YAML: " + e.getOriginalMessage());
        }
    }

    private static Node node(Path file, JsonParser p, int[] count) throws IOException {
        if (++count[0] > MAX_NODES) {
            throw new ExperimentFileException(file, line(p), "more than " + MAX_NODES + " values: an experiment file"
                    + " names its factors' values, not data");
        }
        int line = line(p);
        JsonToken t = p.currentToken();
        if (t == JsonToken.START_OBJECT) {
            Map<String, Node> entries = new LinkedHashMap<>();
            Map<String, Integer> keyLines = new LinkedHashMap<>();
            while (p.nextToken() == JsonToken.FIELD_NAME) {
                String key = p.currentName();
                int keyLine = line(p);
                if (entries.containsKey(key)) {
                    throw new ExperimentFileException(file, keyLine, "'" + key + "' is given twice in one mapping"
                            + " (first on line " + keyLines.get(key) + "): each key is given once");
                }
                p.nextToken();
                keyLines.put(key, keyLine);
                entries.put(key, atKey(node(file, p, count), keyLine));
            }
            return new Mapping(Collections.unmodifiableMap(entries), Collections.unmodifiableMap(keyLines), line);
        }
        if (t == JsonToken.START_ARRAY) {
            List<Node> items = new ArrayList<>();
            while (p.nextToken() != JsonToken.END_ARRAY) {
                items.add(node(file, p, count));
            }
            return new Sequence(List.copyOf(items), line);
        }
        return new Scalar(t == JsonToken.VALUE_NULL ? "" : p.getText(), t, line);
    }

    /**
     * A block mapping or list begins at its first item, a line below its key: an error about it as a
     * whole is told at the key's line.
     */
    private static Node atKey(Node n, int keyLine) {
        if (n instanceof Mapping m) {
            return new Mapping(m.entries(), m.keyLines(), keyLine);
        }
        if (n instanceof Sequence s) {
            return new Sequence(s.items(), keyLine);
        }
        return n;
    }

    private static int line(JsonParser p) {
        return p.currentTokenLocation().getLineNr();
    }
}
