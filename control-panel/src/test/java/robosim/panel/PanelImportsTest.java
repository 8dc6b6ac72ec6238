package robosim.panel;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The panel's packages point one way: the model knows no Swing, sockets or processes (so it is
 * tested headless), the network and process packages no Swing, and nothing but the window knows
 * the window.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class PanelImportsTest {
    @ParameterizedTest
    @CsvSource({
        "model, javax.swing. java.awt. java.net. robosim.panel.net. robosim.panel.process. robosim.panel.window.",
        "net, javax.swing. java.awt. robosim.panel.process. robosim.panel.window.",
        "process, javax.swing. java.awt. robosim.panel.net. robosim.panel.window.",
    })
    void aPackageImportsNothingItMustNot(String pkg, String forbidden) throws IOException {
        Path dir = Path.of(System.getProperty("basedir", "."), "src/main/java/robosim/panel", pkg);
        List<String> offending = new ArrayList<>();
        try (Stream<Path> files = Files.list(dir)) {
            for (Path f : files.toList()) {
                for (String line : Files.readAllLines(f)) {
                    for (String prefix : forbidden.split(" ")) {
                        if (line.startsWith("import " + prefix) || line.startsWith("import static " + prefix)) {
                            offending.add(f.getFileName() + ": " + line);
                        }
                    }
                }
            }
        }
        assertEquals(List.of(), offending, "package robosim.panel." + pkg);
    }
}
