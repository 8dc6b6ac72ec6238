package robosim.experiment;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/** The fingerprint that ties a results folder to the runs of the experiment that made it. */
public final class ExperimentFiles {
    private static final ObjectMapper JSON = new ObjectMapper();

    private ExperimentFiles() {
    }

    /**
     * What the experiment's runs are: its world, programs, comms, combinations, replicates, seeds, step
     * limit and aggregates as the file gives them, and the bytes of the world files its runs name. Not
     * its name, plots, kept metrics or comments: a file changed only in those keeps its records, so a
     * new plot needs no new runs. Not the programs' code either: a rebuilt program needs a new folder.
     *
     * @param e the experiment
     * @return the first 16 hex digits of a SHA-256 over them
     * @throws IOException if a world file cannot be read
     */
    public static String fingerprint(Experiment e) throws IOException {
        Map<String, Object> what = new LinkedHashMap<>();
        Experiment.WorldTemplate w = e.world();
        what.put("world", List.of(text(w.file()), texts(w.cells()), text(w.cellSize()), text(w.mazeSeed()),
                text(w.robotFile()), texts(w.properties())));
        List<Object> programs = new ArrayList<>();
        for (Experiment.ProgramTemplate p : e.programs()) {
            programs.add(List.of(text(p.className()), text(p.count()), texts(p.args()), text(p.link())));
        }
        what.put("programs", programs);
        Experiment.CommsTemplate c = e.comms();
        what.put("comms", c == null ? List.of() : List.of(text(c.range()), text(c.loss()), text(c.latency()),
                text(c.wallsBlock())));
        what.put("combinations", e.combinations());
        what.put("replicates", e.replicates());
        what.put("firstSeed", e.firstSeed());
        what.put("steps", e.steps());
        what.put("aggregates", e.aggregates().toString());
        if (w.file() != null) {
            Set<Path> files = new LinkedHashSet<>();
            for (int i = 0; i < e.runCount(); i++) {
                files.add(((RunSpec.FilePlan) e.run(i).world()).file());
            }
            List<String> worlds = new ArrayList<>();
            for (Path f : files) {
                worlds.add(f + " " + (Files.isReadable(f) ? fingerprint(Files.readAllBytes(f)) : "missing"));
            }
            what.put("worldFiles", worlds);
        }
        try {
            return fingerprint(JSON.writeValueAsBytes(what));
        } catch (JsonProcessingException x) {
            throw new IllegalStateException("an experiment's description did not serialise", x);
        }
    }

    private static String text(Template t) {
        return t == null ? "" : t.text();
    }

    private static List<String> texts(List<Template> ts) {
        return ts == null ? List.of() : ts.stream().map(ExperimentFiles::text).toList();
    }

    private static Map<String, String> texts(Map<String, Template> ts) {
        Map<String, String> out = new LinkedHashMap<>();
        ts.forEach((k, v) -> out.put(k, text(v)));
        return out;
    }

    /**
     * @param text a text
     * @return the first 16 hex digits of the SHA-256 of its UTF-8 bytes
     */
    static String fingerprint(String text) {
        return fingerprint(text.getBytes(StandardCharsets.UTF_8));
    }

    private static String fingerprint(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes), 0, 8);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("this JDK has no SHA-256", e);
        }
    }
}
