package robosim.scout;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The Scout is built on the generic robot package alone: it does not borrow from the Pioneer's ARIA
 * API, reach the Environment's internals, open sockets of its own, draw, or print.
 */
class ScoutImportsTest {
    private static List<Path> sources() throws IOException {
        Path dir = ScriptedScout.scoutFile().getParent().getParent().getParent().resolve("scout-api/src/main/java");
        try (Stream<Path> files = Files.walk(dir)) {
            List<Path> java = files.filter(p -> p.toString().endsWith(".java")).toList();
            assertTrue(java.size() >= 7, "found the sources in " + dir);
            return java;
        }
    }

    @ParameterizedTest(name = "scout-api does not use {0}")
    @CsvSource(delimiter = ';', value = {
            "the ARIA API (robosim.aria);\\brobosim\\.aria\\b",
            "the Environment (robosim.env);\\brobosim\\.env\\b",
            "the network (java.net);\\bjava\\.net\\.",
            "AWT (java.awt);\\bjava\\.awt\\b",
            "Swing (javax.swing);\\bjavax\\.swing\\b",
            "System.out or System.err;\\bSystem\\s*\\.\\s*(out|err)\\b"})
    void scoutApiDoesNotUse(String what, String regex) throws IOException {
        Pattern p = Pattern.compile(regex);
        List<String> offences = sources().stream().filter(f -> {
            try {
                return p.matcher(Files.readString(f)).find();
            } catch (IOException e) {
                throw new IllegalStateException(e);
            }
        }).map(f -> f.getFileName().toString()).toList();
        assertEquals(List.of(), offences);
    }
}
