package robosim.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** The model and the robots stay apart from Swing, so they are tested headless, and never reach the window. */
class ModelImportsTest {
    private static List<String> offending(String pkg, String... banned) throws IOException {
        Path dir = Path.of("src/main/java/robosim/remote").resolve(pkg);
        try (Stream<Path> files = Files.list(dir)) {
            return files.filter(f -> f.toString().endsWith(".java")).flatMap(f -> {
                try {
                    return Files.readAllLines(f).stream().filter(l -> l.startsWith("import "))
                            .filter(l -> Stream.of(banned).anyMatch(l::contains)).map(l -> f.getFileName() + ": " + l);
                } catch (IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            }).toList();
        }
    }

    @Test
    void theModelImportsNoSwingAwtRobotsOrWindow() throws IOException {
        assertEquals(List.of(), offending("", "javax.swing", "java.awt", "robosim.remote.window", "robosim.remote.robot",
                "robosim.aria", "robosim.scout"));
    }

    @Test
    void theRobotsImportNoSwingAwtOrWindow() throws IOException {
        assertEquals(List.of(), offending("robot", "javax.swing", "java.awt", "robosim.remote.window"));
    }
}
