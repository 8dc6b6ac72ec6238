package robosim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The 3D renderer draws and does no I/O; the window neither opens files nor sockets (the launcher
 * feeds it); the network client draws nothing and the drawing knows no network; nothing in the
 * viewer prints (docs/DESIGN.md, "Rules the code keeps", rules 3 and 6).
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class ViewerPackagesImportTest {
    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "view3d | import java.io.;import java.net.;import java.nio.;import javax.imageio.;import java.util.logging.;System.out;System.err",
        "window | import java.net.;import java.nio.;import javax.imageio.;System.out;System.err",
        "replay | import java.net.;System.out;System.err",
        "net | import java.awt.;import javax.swing.;import javax.imageio.;import robosim.viewer.draw.;import robosim.viewer.view3d.;import robosim.viewer.window.;import robosim.viewer.replay.;System.out;System.err",
        "draw | import java.net.;import java.util.logging.;import robosim.viewer.net.;import robosim.viewer.window.;import robosim.viewer.replay.;System.out;System.err"})
    void packageKeepsToItsRole(String pkg, String forbidden) throws IOException {
        Path dir = Path.of(System.getProperty("basedir", "."), "src/main/java/robosim/viewer", pkg);
        List<String> rules = List.of(forbidden.split(";"));
        try (Stream<Path> files = Files.list(dir)) {
            List<String> offending = files.flatMap(f -> {
                try {
                    return Files.readAllLines(f).stream().filter(l -> rules.stream().anyMatch(l::contains))
                            .map(l -> f.getFileName() + ": " + l.strip());
                } catch (IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            }).toList();
            assertEquals(List.of(), offending, pkg + " must keep to its role");
        }
    }
}
